// The master log format (calibration/master_log.hpp): round trip, and every
// bad line named by file:line.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "calibration/master_log.hpp"

namespace sreh {
namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::path(testing::TempDir()) / name;
  std::ofstream(path) << text;
  return path.string();
}

std::string error_of(const std::string& text) {
  try {
    read_master_log(write_temp("bad.csv", text));
  } catch (const CalibrationInputError& e) {
    return e.what();
  }
  return "";
}

TEST(MasterLog, WrittenRowsReadBack) {
  std::ostringstream out;
  write_master_log_header(out);
  ProcessDataOut o;
  o.motor_on = true;
  o.target_raw = -65536;
  ProcessDataIn i;
  i.position_raw = 12345;
  write_master_log_row(out, 0.002, encode(o), encode(i), std::nullopt);
  write_master_log_row(out, 0.004, encode(o), encode(i), 31.5);
  EXPECT_EQ(out.str(),
            "t_s,pd_out,pd_in,temperature_C\n"
            "0.002000,ffff00000001,00003039000000,\n"
            "0.004000,ffff00000001,00003039000000,31.5\n");
  const MasterLog log = read_master_log(write_temp("good.csv", out.str()));
  ASSERT_EQ(log.rows.size(), 2u);
  EXPECT_TRUE(log.has_temperature);
  EXPECT_EQ(decode_out(log.rows[0].pd_out), o);
  EXPECT_EQ(decode_in(log.rows[1].pd_in), i);
  EXPECT_FALSE(log.rows[0].temperature_C);
  EXPECT_DOUBLE_EQ(*log.rows[1].temperature_C, 31.5);
  EXPECT_EQ(log.rows[1].line, 3);
  // Half a wire count above the floored reading (A-CAL-1).
  EXPECT_DOUBLE_EQ(logged_position_deg(log.rows[0].pd_in), 12345.5 * 360.0 / 65536.0);
}

TEST(MasterLog, ThreeColumnsWithoutTemperature) {
  const MasterLog log = read_master_log(write_temp("three.csv", "t_s,pd_out,pd_in\n0.002,000000000001,00000000000002\n"
                                                               "0.004,000000000001,00000000000002\n"));
  EXPECT_FALSE(log.has_temperature);
  EXPECT_EQ(log.rows.size(), 2u);
}

TEST(MasterLog, BadLinesNamedByFileAndLine) {
  EXPECT_NE(error_of("t,pd_out,pd_in\n").find("bad.csv:1: header"), std::string::npos);
  EXPECT_NE(error_of("t_s,pd_out,pd_in\n0.002,0000000001,00000000000002\n").find("bad.csv:2: pd_out \"0000000001\": expected 12 hex digits"),
            std::string::npos);
  EXPECT_NE(error_of("t_s,pd_out,pd_in\n0.002,000000000001,0000000000000g\n").find("bad.csv:2: pd_in"), std::string::npos);
  EXPECT_NE(error_of("t_s,pd_out,pd_in\n0.004,000000000001,00000000000002\n0.002,000000000001,00000000000002\n")
                .find("bad.csv:3: t_s 0.002 does not increase"),
            std::string::npos);
  EXPECT_NE(error_of("t_s,pd_out,pd_in\n0.002,000000000001\n").find("bad.csv:2: 2 columns"), std::string::npos);
  EXPECT_NE(error_of("t_s,pd_out,pd_in\nx,000000000001,00000000000002\n").find("bad.csv:2: t_s \"x\": not a number"),
            std::string::npos);
}

} // namespace
} // namespace sreh
