// One trace row per IO-Link cycle (twin/trace.hpp, issue 13): the device's
// Telemetry by value plus what only the twin knows, the one schema the CSV,
// the video overlay and the report read.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "device_logic/units.hpp"
#include "twin/plant.hpp"
#include "twin/twin.hpp"

namespace sreh {
namespace {

std::string csv_line(const TraceRow& row) {
  std::ostringstream out;
  write_trace_row(out, row);
  return out.str();
}

// Motor on, then an absolute move to 90 deg with set 1 (manual 3.2 T1, T3).
void start_move(Twin& twin) {
  ProcessDataOut pd;
  pd.motor_on = true;
  twin.set_pd_out(pd);
  for (int i = 0; i < 50 && !twin.pd_in().ready; ++i) twin.run_cycle();
  ASSERT_TRUE(twin.pd_in().ready);
  pd.target_raw = static_cast<int32_t>(deg_to_wire_counts(90.0));
  pd.parameter_set = 1;
  pd.move = true;
  twin.set_pd_out(pd);
}

TEST(TraceRow, CarriesTheDeviceTelemetryAndThePlantsMeasurements) {
  Twin twin(TwinConfig{});
  start_move(twin);
  for (int i = 0; i < 20; ++i) twin.run_cycle(); // mid-move
  const TraceRow& row = twin.last_row();
  const Telemetry tel = twin.telemetry();
  EXPECT_EQ(row.state, State::Busy);
  EXPECT_TRUE(row.moving);
  EXPECT_EQ(row.moves_started, 1u);
  EXPECT_EQ(row.setpoint_deg, tel.setpoint_deg);
  EXPECT_EQ(row.position_deg, tel.position_deg);
  EXPECT_EQ(row.tracking_error_deg, tel.tracking_error_deg);
  EXPECT_EQ(row.tolerance_deg, tel.tolerance_deg);
  EXPECT_GT(row.setpoint_deg, 0.0);
  // Where the module measures what the firmware only commands: the plant's values.
  EXPECT_EQ(row.torque_Nm, twin.plant().applied_torque_Nm());
  EXPECT_EQ(row.supply_V, twin.plant().sensors().supply_V);
  EXPECT_EQ(row.temperature_C, twin.plant().sensors().temperature_C);
  EXPECT_EQ(row.pd_out, encode(twin.pd_out()));
  EXPECT_DOUBLE_EQ(row.t_s, twin.time_s());
}

TEST(TraceRow, LastRowIsTheSameWhetherTheTraceIsKeptOrNot) {
  TwinConfig keep;
  TwinConfig none;
  none.record_trace = false;
  Twin a(keep), b(none);
  start_move(a);
  start_move(b);
  for (int i = 0; i < 30; ++i) {
    a.run_cycle();
    b.run_cycle();
  }
  ASSERT_FALSE(a.trace().empty());
  EXPECT_TRUE(b.trace().empty());
  EXPECT_EQ(csv_line(a.last_row()), csv_line(a.trace().back()));
  EXPECT_EQ(csv_line(b.last_row()), csv_line(a.trace().back()));
}

TEST(TraceRow, LedBandIsOffWhileUnpowered_3_1) {
  Twin twin(TwinConfig{});
  start_move(twin);
  twin.run_cycle();
  EXPECT_NE(twin.last_row().led, LedColor::Off); // moving: lit
  twin.power_off();
  twin.run_cycle();
  EXPECT_EQ(twin.last_row().led, LedColor::Off);
}

} // namespace
} // namespace sreh
