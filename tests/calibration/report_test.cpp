// `calibrate --report` (issue 26): the page shows, per log, the logged
// position against the twin's with the start and the fitted card and their
// error, the constants with their intervals and the correlation.
#include "calibration/report.hpp"

#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>
#include <unistd.h>

#include "calibration_rig.hpp"

namespace sreh {
namespace {

std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A fit whose "fitted" card is the module that recorded the log: its replay
// gives the logged frames back bit for bit, so what the page shows for it is
// only the wire's quantisation (the encoder against the logged counts, under
// one count), and more than that for the start card.
TEST(CalibrationReport, ShowsEachLogWithStartAndFittedCard) {
  if (!calibration_reports_available()) GTEST_SKIP() << "built without renders";
  Scenario plan = test::plan_scenario(5000);
  plan.steps.resize(3 + 4 * 2); // motor on, wait, hold, two moves
  const ModelCard hidden = test::card_with({{"coulomb_friction", 0.0054}});
  MasterLog log = test::record_log(plan, hidden);
  for (std::size_t k = 0; k < log.rows.size(); k += 100) log.rows[k].temperature_C = 25.0; // polled now and then
  FitCase c;
  c.log = log;
  c.setup = replay_setup(log, InertiaLoad{5000}, &plan);

  FitResult fit;
  fit.card = hidden;
  fit.converged = true;
  fit.iterations = 4;
  fit.constants = {{"coulomb_friction", "N m", 0.0054, 0.004, 0.0050, 0.0058, true, ""},
                   {"viscous_friction", "N m s/rad", 1e-5, 1e-5, 0.0, 3e-5, false, "interval wider than +-25 %"}};
  fit.correlation = {{1.0, 0.97}, {0.97, 1.0}}; // above kStrongCorrelation
  const auto dir = std::filesystem::temp_directory_path() / ("sreh_calibration_report_test_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  const std::filesystem::path index = write_calibration_report(dir, {c}, default_model_card(), fit);
  const std::string html = read_all(index);

  EXPECT_NE(html.find("CONVERGED"), std::string::npos);
  EXPECT_EQ(count(html, "<svg"), 3u); // position, error, temperature
  EXPECT_NE(html.find("twin, start card"), std::string::npos);
  EXPECT_NE(html.find("twin, fitted card"), std::string::npos);
  EXPECT_NE(html.find("+-1 wire count"), std::string::npos);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(html, m, std::regex(R"(rms error ([0-9.]+) deg with the start card, ([0-9.]+) deg fitted)")));
  const double wire_count_deg = 360.0 / 65536;
  EXPECT_LT(std::stod(m[2]), wire_count_deg / 2);
  EXPECT_GT(std::stod(m[1]), std::stod(m[2]));
  // The constants table: change and the unidentified one with its reason; the strong correlation in bold.
  EXPECT_NE(html.find("+35.0 %"), std::string::npos); // 0.004 -> 0.0054
  EXPECT_NE(html.find("no</span> interval wider than +-25 %"), std::string::npos);
  EXPECT_NE(html.find("<b>+0.97</b>"), std::string::npos);
  std::filesystem::remove_all(dir);
}

} // namespace
} // namespace sreh
