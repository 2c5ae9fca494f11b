// The twin (issue 5): the device logic coupled to the MuJoCo plant on
// integer clocks. A PLC's view: process data per IO-Link cycle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "device_logic/units.hpp"
#include "twin/plant.hpp"
#include "twin/twin.hpp"

namespace sreh {
namespace {

// Runs cycles until pred holds; returns the number of cycles or -1.
template <class Pred>
int run_until(Twin& twin, Pred pred, int max_cycles) {
  for (int i = 0; i < max_cycles; ++i) {
    twin.run_cycle();
    if (pred()) return i + 1;
  }
  return -1;
}

void write_u16(Twin& twin, uint16_t index, uint8_t sub, uint16_t value) {
  const uint8_t bytes[2] = {static_cast<uint8_t>(value >> 8), static_cast<uint8_t>(value & 0xFF)};
  ASSERT_TRUE(twin.isdu_write(index, sub, bytes).ok()) << index << "." << int{sub};
}

// Manual 3.2 T1, 3.4: motor on, then an absolute move of 90 deg with
// parameter set 1 configured for the actual load.
void switch_on_and_move(Twin& twin, double target_deg) {
  ProcessDataOut pd;
  pd.motor_on = true;
  twin.set_pd_out(pd);
  ASSERT_GT(run_until(twin, [&] { return twin.pd_in().ready; }, 100), 0);
  pd.target_raw = static_cast<int32_t>(deg_to_wire_counts(target_deg));
  pd.parameter_set = 1;
  pd.move = true;
  twin.set_pd_out(pd);
}

TwinConfig twin_config_with(LoadSpec load) {
  TwinConfig c;
  c.load = std::move(load);
  return c;
}

TwinConfig twin_config_2000() {
  TwinConfig c;
  c.load = InertiaLoad{2000};
  return c;
}

TEST(Twin, ReportsActualLoadInertia) {
  Twin twin(twin_config_with(DiskLoad{0.3, 0.08, 0.01}));
  EXPECT_NEAR(twin.load_inertia_gcm2(), 9600.0, 1e-6);
}

TEST(Twin, RefusesLoadBeyondModuleLimit_6_2) {
  EXPECT_THROW({ Twin t(twin_config_with(InertiaLoad{20000})); }, std::invalid_argument);
}

TEST(Twin, RefusesCycleNotAMultipleOfPhysicsStep) {
  TwinConfig c;
  c.cycle_s = 0.00215;
  EXPECT_THROW({ Twin t(c); }, std::invalid_argument);
}

TEST(Twin, ClocksAreIntegerCycles) {
  Twin twin(TwinConfig{});
  for (int i = 0; i < 500; ++i) twin.run_cycle();
  EXPECT_EQ(twin.cycles(), 500u);
  EXPECT_EQ(twin.time_s(), 500 * 0.002);
  EXPECT_EQ(twin.plant().steps(), 500u * 20u);
  EXPECT_EQ(twin.trace().size(), 500u);
}

TEST(Twin, NinetyDegreeMoveCompletes_3_5_2) {
  Twin twin(twin_config_2000());
  write_u16(twin, 65, 4, 2000); // parameter set 1: configured load = actual load
  switch_on_and_move(twin, 90.0);
  ASSERT_GT(run_until(twin, [&] { return twin.pd_in().done; }, 1000), 0);
  const Telemetry t = twin.telemetry();
  EXPECT_EQ(t.state, State::Done);
  EXPECT_NEAR(t.position_deg, 90.0, 0.1); // default tolerance 0.1 deg (index 64.5)
  EXPECT_EQ(t.error_code, 0);
  EXPECT_EQ(t.warning_code, 0);
  EXPECT_NEAR(rad_to_deg(twin.plant().angle_rad()), 90.0, 0.1); // clockwise = physical positive (manual 4.2)
  const ProcessDataIn in = twin.pd_in();
  EXPECT_NEAR(wire_counts_to_deg(in.position_raw), 90.0, 0.1);

  ASSERT_EQ(twin.moves().size(), 1u);
  const MoveRecord& m = twin.moves()[0];
  EXPECT_TRUE(m.completed());
  EXPECT_GT(m.travel_s, 0.02);
  ASSERT_TRUE(m.settling_s && m.positioning_s);
  EXPECT_GE(*m.settling_s, 0.0);
  EXPECT_NEAR(*m.positioning_s, m.travel_s + *m.settling_s, 1e-12);
  EXPECT_NEAR(m.target_deg, 90.0, 1e-6);
  EXPECT_GT(m.max_tracking_error_deg, 0.0);
  EXPECT_LT(m.max_tracking_error_deg, 1.0); // below the default 87.1 limit
}

TEST(Twin, SameRunTwiceGivesIdenticalTraceBytes) {
  auto run_once = [] {
    Twin twin(twin_config_2000());
    write_u16(twin, 65, 4, 2000);
    switch_on_and_move(twin, 90.0);
    for (int i = 0; i < 200; ++i) twin.run_cycle();
    std::ostringstream csv;
    write_trace_csv(csv, twin.trace());
    return csv.str();
  };
  const std::string a = run_once();
  EXPECT_EQ(a, run_once());
  EXPECT_EQ(a.substr(0, a.find('\n')),
            "t_s,state,setpoint_deg,position_deg,tracking_error_deg,velocity_dps,torque_Nm,supply_V,temperature_C,"
            "error_code,warning_code,pd_out_hex,pd_in_hex,led,torque_limit_Nm,external_torque_Nm,iolink_led");
  EXPECT_NE(a.find("Done"), std::string::npos);
}

TEST(Twin, HardStopCausesTrackingError_7_2_114_5) {
  TwinConfig c = twin_config_2000();
  c.hard_stops = {HardStop{45.0}};
  Twin twin(c);
  write_u16(twin, 65, 4, 2000);
  switch_on_and_move(twin, 90.0);
  ASSERT_GT(run_until(twin, [&] { return twin.pd_in().error; }, 1000), 0);
  EXPECT_NE(twin.telemetry().error_code & 0x08, 0); // bit 3: position tracking error (manual 2.4)
  // At the stop or bounced off it: the rotor's momentum, stored in the
  // compliance at the impact (A-TWIN-20), pushes the flange back.
  EXPECT_GT(rad_to_deg(twin.plant().angle_rad()), 40.0);
  EXPECT_LT(rad_to_deg(twin.plant().angle_rad()), 45.5);
  ASSERT_EQ(twin.moves().size(), 1u);
  EXPECT_FALSE(twin.moves()[0].completed());
  EXPECT_FALSE(twin.moves()[0].positioning_s.has_value());
}

// The hardest impact: no load, the module's top speed (manual 3.5.3, 4300
// deg/s at 24 V) into a post. The flange stops at it and bounces back (the
// rotor's momentum stored in the compliance, A-TWIN-20) and coasts (the
// motor is off after the tracking error), but never passes it.
TEST(Twin, HardStopAtTopSpeedWithNoLoadIsNotPassed_7_2_114_5) {
  for (double stop_deg : {20.0, 33.3, 47.1, 61.9}) {
    SCOPED_TRACE("stop at " + std::to_string(stop_deg) + " deg");
    TwinConfig c;
    c.record_trace = false;
    c.hard_stops = {HardStop{stop_deg}};
    Twin twin(c);
    write_u16(twin, 65, 1, 43000);
    switch_on_and_move(twin, 90.0);
    double furthest_deg = 0;
    for (int i = 0; i < 250; ++i) { // 0.5 s
      twin.run_cycle();
      furthest_deg = std::max(furthest_deg, rad_to_deg(twin.plant().angle_rad()));
    }
    EXPECT_GT(furthest_deg, stop_deg - 2.0); // it got there
    EXPECT_LT(furthest_deg, stop_deg + 1.5); // and not through
    EXPECT_NE(twin.telemetry().error_code & 0x08, 0); // tracking error (manual 2.4, 114.5)
  }
}

TEST(Twin, LinkDownWhileMotorOnIsAnError_5) {
  Twin twin(TwinConfig{});
  ProcessDataOut pd;
  pd.motor_on = true;
  twin.set_pd_out(pd);
  ASSERT_GT(run_until(twin, [&] { return twin.pd_in().ready; }, 100), 0);
  twin.set_link_up(false);
  const ProcessDataIn before = twin.pd_in();
  for (int i = 0; i < 100; ++i) twin.run_cycle();
  EXPECT_EQ(twin.pd_in(), before); // the master receives nothing while the link is down
  EXPECT_NE(twin.telemetry().error_code & 0x04, 0); // bit 2: communication
}

TEST(Twin, PowerCycleKeepsAbsolutePosition_4_1) {
  Twin twin(twin_config_2000());
  write_u16(twin, 65, 4, 2000);
  switch_on_and_move(twin, 90.0);
  ASSERT_GT(run_until(twin, [&] { return twin.pd_in().done; }, 1000), 0);
  twin.set_pd_out(ProcessDataOut{});
  for (int i = 0; i < 10; ++i) twin.run_cycle();
  twin.power_cycle();
  for (int i = 0; i < 10; ++i) twin.run_cycle();
  EXPECT_EQ(twin.telemetry().state, State::MotorOff);
  EXPECT_NEAR(twin.telemetry().position_deg, 90.0, 0.1);
}

TEST(Twin, ExternalTorqueIsResistedWhileHolding) {
  Twin twin(twin_config_2000());
  write_u16(twin, 65, 4, 2000);
  switch_on_and_move(twin, 90.0);
  ASSERT_GT(run_until(twin, [&] { return twin.pd_in().done; }, 1000), 0);
  twin.set_external_torque(0.2);
  for (int i = 0; i < 100; ++i) twin.run_cycle();
  EXPECT_NEAR(twin.telemetry().position_deg, 90.0, 1.0);
  EXPECT_NEAR(twin.trace().back().external_torque_Nm, 0.2, 1e-12);
  EXPECT_LT(twin.trace().back().torque_Nm, -0.1); // the motor holds against it
}

// A-TWIN-30: a blocked flange stays where it is, whatever the motor does;
// the device's own monitor then reports the tracking error (manual 7.2 114.5).
TEST(Twin, BlockedFlangeHoldsAndGivesTrackingError_7_2_114_5) {
  Twin twin(twin_config_2000());
  write_u16(twin, 65, 4, 2000);
  switch_on_and_move(twin, 120.0);
  ASSERT_GT(run_until(twin, [&] { return rad_to_deg(twin.plant().angle_rad()) > 10.0; }, 200), 0);
  twin.set_flange_blocked(true);
  const double held_rad = twin.plant().angle_rad();
  // The clamp is a stiff MuJoCo constraint (A-TWIN-30), not an overwrite:
  // it gives by far less than one wire count (9.6e-5 rad) while the motor
  // pushes. The largest give is the first cycle, while the clamp stops the
  // moving flange and, through the gear's spring, the rotor: 2.2e-5 rad
  // with the issue-35 planetary (2500 N m/rad, 7x the former spring, so
  // the rotor's momentum reaches the clamp within the cycle); below a
  // quarter of a wire count.
  double max_dev_rad = 0;
  ASSERT_GT(run_until(twin, [&] {
              max_dev_rad = std::max(max_dev_rad, std::abs(twin.plant().angle_rad() - held_rad));
              return twin.pd_in().error;
            }, 500), 0);
  EXPECT_LT(max_dev_rad, 0.25 * 9.6e-5);
  // Only the constraint's give moves it: at most ~1 deg/s against the rotor
  // winding the compliance (held within a quarter count above).
  EXPECT_NEAR(twin.plant().velocity_rad_s(), 0.0, 0.02);
  EXPECT_NE(twin.telemetry().error_code & 0x08, 0);
  EXPECT_FALSE(twin.moves().back().completed());
}

TEST(Twin, ReleasedFlangeMovesAgain) {
  Twin twin(twin_config_2000());
  write_u16(twin, 65, 4, 2000);
  twin.set_flange_blocked(true);
  twin.set_flange_blocked(false);
  switch_on_and_move(twin, 45.0);
  ASSERT_GT(run_until(twin, [&] { return twin.pd_in().done; }, 500), 0);
  EXPECT_NEAR(twin.telemetry().position_deg, 45.0, 0.1);
}

// A-TWIN-31: a new ambient is followed with the model's time constants.
TEST(Twin, AmbientChangeIsFollowedNotJumped) {
  TwinConfig c;
  c.thermal.time_scale = 200; // minutes in seconds (A-TWIN-THERMAL-3)
  Twin twin(c);
  twin.set_ambient_C(45.0);
  twin.run_cycle();
  EXPECT_LT(twin.plant().sensors().temperature_C, 25.1);
  for (int i = 0; i < 1000; ++i) twin.run_cycle(); // 2 s x 200
  const double t = twin.plant().sensors().temperature_C;
  EXPECT_GT(t, 26.0);
  EXPECT_LT(t, 45.0);
}

TEST(Twin, GhostShowsThePlannedSetpoint) {
  Twin twin(twin_config_2000());
  write_u16(twin, 65, 4, 2000);
  switch_on_and_move(twin, 90.0);
  for (int i = 0; i < 20; ++i) twin.run_cycle(); // mid-move
  const Plant& plant = twin.plant();
  const int mocap = plant.model()->body_mocapid[mj_name2id(plant.model(), mjOBJ_BODY, "setpoint_ghost")];
  const double* q = plant.data()->mocap_quat + 4 * mocap;
  const double ghost_rad = -2 * std::atan2(q[3], q[0]); // rotation about -z
  EXPECT_NEAR(rad_to_deg(ghost_rad), twin.telemetry().setpoint_deg, 0.01);
}

} // namespace
} // namespace sreh

namespace sreh {
namespace {

// Runs a PLC program that moves between 0 and `angle_deg` with parameter set
// 1, `dwell_cycles` IO-Link cycles at each end, until `pred` or max_cycles.
template <class Pred>
int cycle_moves(Twin& twin, double angle_deg, int dwell_cycles, int max_cycles, Pred pred) {
  ProcessDataOut pd;
  pd.motor_on = true;
  pd.parameter_set = 1;
  bool at_far_end = false;
  int wait = 0;
  for (int k = 0; k < max_cycles; ++k) {
    const ProcessDataIn in = twin.pd_in();
    if (in.ready && !pd.move && wait-- <= 0) {
      pd.target_raw = at_far_end ? 0 : static_cast<int32_t>(deg_to_wire_counts(angle_deg));
      pd.move = true;
      at_far_end = !at_far_end;
    } else if (in.done && pd.move) {
      pd.move = false;
      wait = dwell_cycles;
    }
    twin.set_pd_out(pd);
    twin.run_cycle();
    if (pred()) return k + 1;
  }
  return -1;
}

TwinConfig heavy_config(double time_scale) {
  TwinConfig c;
  c.load = InertiaLoad{15000};
  c.thermal.time_scale = time_scale;
  c.record_trace = false;
  return c;
}

// A-TWIN-THERMAL: sustained fast cycling with the heaviest load reaches the
// temperature warning (manual 2.4 warning bit 7, 115.1) and then the
// temperature error (error bit 5, 114.3). With the issue-35 card this duty
// settles ~11 K above the room (docs/model-card.md "Thermal steady state"),
// so it overheats a hot machine: 66 degC ambient, as the scenario
// error_114_3_overtemperature. The winding (36 s) alone adds at most
// ~4 K over the housing: the warning comes after the first minute, and the
// trip needs the housing (30 min) to warm by ~5 K, so it takes more than
// 10 min and less than three housing time constants.
// time_scale 100: 60 s simulated = 100 min thermal.
TEST(Twin, HeavyFastCyclingOverheats_7_2_114_3) {
  TwinConfig c = heavy_config(100.0);
  c.thermal.ambient_C = 66.0;
  Twin twin(c);
  const uint8_t load[2] = {static_cast<uint8_t>(15000 >> 8), static_cast<uint8_t>(15000 & 0xFF)};
  ASSERT_TRUE(twin.isdu_write(65, 4, load).ok());
  int warn = -1;
  double warn_C = 0;
  const int error = cycle_moves(twin, 180.0, 0, 30000, [&] {
    if (warn < 0 && (twin.telemetry().warning_code & 0x80) != 0) {
      warn = static_cast<int>(twin.cycles());
      warn_C = twin.telemetry().temperature_C;
    }
    return (twin.telemetry().error_code & 0x20) != 0;
  });
  ASSERT_GT(warn, 0);
  EXPECT_GE(warn_C, 70.0);
  EXPECT_GT(warn * 0.002 * 100.0, 60.0); // not within the first minute
  ASSERT_GT(error, warn);
  EXPECT_GT(twin.telemetry().temperature_C, 74.9); // cooling since the error tick
  EXPECT_GT(error * 0.002 * 100.0, 600.0);  // the housing has to warm
  EXPECT_LT(error * 0.002 * 100.0, 5400.0); // within three housing time constants
  EXPECT_EQ(twin.telemetry().state, State::ErrorOff); // manual 2.4: the motor is switched off
}

// Normal duty: 90 deg moves with 2000 g cm^2 and 0.5 s pauses stay far below.
TEST(Twin, NormalDutyStaysCool) {
  TwinConfig c = heavy_config(20.0);
  c.load = InertiaLoad{2000};
  Twin twin(c);
  const uint8_t load[2] = {static_cast<uint8_t>(2000 >> 8), static_cast<uint8_t>(2000 & 0xFF)};
  ASSERT_TRUE(twin.isdu_write(65, 4, load).ok());
  cycle_moves(twin, 90.0, 250, 15000, [] { return false; }); // 10 min thermal time
  EXPECT_LT(twin.telemetry().temperature_C, 40.0);
  EXPECT_EQ(twin.telemetry().warning_code, 0);
}

} // namespace
} // namespace sreh
