// Issue 5 acceptance on the MuJoCo twin: tracking and settling emerge from
// physics. Loads 0..15000 g cm^2 x angles 1..1080 deg with the load
// configured (manual 3.5.6), 4300 deg/s at 24 V vs 19 V (manual 3.5.3), an
// unknown heavy load (7.2 114.5).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "device_logic/planner.hpp"
#include "device_logic/units.hpp"
#include "twin/plant.hpp"
#include "tests/twin/twin_helpers.hpp"
#include "twin/twin.hpp"

namespace sreh {
namespace {

using test::write_raw;

struct Outcome {
  bool done = false;
  uint8_t error_code = 0;
  double position_deg = 0;
};

// Motor on, one absolute move with parameter set 1, until Done or an error.
Outcome move(Twin& twin, double target_deg, double max_s) {
  ProcessDataOut pd;
  pd.motor_on = true;
  twin.set_pd_out(pd);
  for (int i = 0; i < 50 && !twin.pd_in().ready; ++i) twin.run_cycle();
  EXPECT_TRUE(twin.pd_in().ready);
  pd.target_raw = static_cast<int32_t>(deg_to_wire_counts(target_deg));
  pd.parameter_set = 1;
  pd.move = true;
  twin.set_pd_out(pd);
  const int cycles = static_cast<int>(max_s / 0.002);
  for (int i = 0; i < cycles; ++i) {
    twin.run_cycle();
    const ProcessDataIn in = twin.pd_in();
    if (in.done || in.error) break;
  }
  const ProcessDataIn in = twin.pd_in();
  return {in.done, in.error_code, wire_counts_to_deg(in.position_raw)};
}

TEST(TwinPhysics, ConfiguredLoadsCompleteAcrossLoadsAndAngles_3_5) {
  for (double load_gcm2 : {0.0, 1000.0, 5000.0, 10000.0, 15000.0}) {
    for (double angle_deg : {1.0, 10.0, 90.0, 360.0, 1080.0}) {
      TwinConfig c;
      c.load = InertiaLoad{load_gcm2};
      c.record_trace = false;
      Twin twin(c);
      write_raw(twin, 65, 4, static_cast<uint16_t>(std::lround(twin.load_inertia_gcm2())));
      const Outcome o = move(twin, angle_deg, 3.0);
      EXPECT_TRUE(o.done) << load_gcm2 << " g cm^2, " << angle_deg << " deg, error " << int{o.error_code};
      EXPECT_NEAR(o.position_deg, angle_deg, 0.1) << load_gcm2 << ", " << angle_deg;
      ASSERT_EQ(twin.moves().size(), 1u);
      // The travel follows the planner: its time is the planned S-curve's.
      const MotionLimits lim = limits_from_parameter_set(3000, 100, 100, std::round(twin.load_inertia_gcm2()));
      const double planned = Profile::rest_to_rest(deg_to_rad(angle_deg), lim).duration_s();
      EXPECT_NEAR(twin.moves()[0].travel_s, planned, 0.0021) << load_gcm2 << ", " << angle_deg;
      EXPECT_LT(twin.moves()[0].max_tracking_error_deg, 0.5);
    }
  }
}

// Manual 3.5.3 / 7.2 114.5: "with lower motor voltage, the maximum possible
// speed decreases proportionally to the voltage": 4300 deg/s at 24 V, about
// 3404 deg/s at 19 V. The back-EMF against the bus voltage limits the
// winding current (A-MOTOR-1, twin/motor_drive.cpp), nothing else.
TEST(TwinPhysics, SpeedLimitFallsWithVoltage_3_5_3) {
  struct Case { double volts, speed_dps; bool completes; };
  for (const Case& k : {Case{24.0, 4300.0, true}, Case{19.0, 3300.0, true}, Case{19.0, 3500.0, false}}) {
    TwinConfig c;
    c.load = InertiaLoad{1000};
    c.supply.voltage_V = k.volts;
    c.record_trace = false;
    Twin twin(c);
    write_raw(twin, 65, 1, static_cast<uint16_t>(k.speed_dps * 10));
    write_raw(twin, 65, 4, 1000);
    const Outcome o = move(twin, 1080, 3.0);
    if (k.completes) {
      EXPECT_TRUE(o.done) << k.volts << " V, " << k.speed_dps << " deg/s, error " << int{o.error_code};
    } else {
      EXPECT_FALSE(o.done) << k.volts << " V, " << k.speed_dps << " deg/s";
      EXPECT_EQ(o.error_code, 1u << 3) << k.volts << " V, " << k.speed_dps << " deg/s"; // tracking error, motor off
    }
  }
}

// Manual 7.2 114.5: a heavy load the parameter set does not know.
TEST(TwinPhysics, UnknownHeavyLoadGivesTrackingError_7_2) {
  TwinConfig c;
  c.load = InertiaLoad{15000};
  Twin twin(c); // set 1 still says 0 g cm^2
  const Outcome o = move(twin, 180, 2.0);
  EXPECT_FALSE(o.done);
  EXPECT_EQ(o.error_code, 1u << 3);
}

// Issue 14: a load configured lighter than it is gets too little
// acceleration feed-forward and a position loop too fast for its actual
// velocity loop: it lags and overshoots more than a matched one (manual
// 3.5.6). At 50 % acceleration, so the stage has the torque to follow: the
// card's 0.57 N m at the flange (docs/model-card.md, issue 35) is 18 %
// above M, so at 100 % a load configured 13 % light already runs into the
// current limit, and a saturated drive lags without overshooting.
TEST(TwinPhysics, UnderconfiguredLoadOvershootsMore_3_5_6) {
  double overshoot[2] = {0, 0};
  double lag[2] = {0, 0};
  const double configured[2] = {15000, 10000};
  for (int i = 0; i < 2; ++i) {
    TwinConfig c;
    c.load = InertiaLoad{15000};
    c.record_trace = false;
    Twin twin(c);
    write_raw(twin, 65, 2, 500); // acceleration 50 %
    write_raw(twin, 65, 4, static_cast<uint16_t>(configured[i]));
    const Outcome o = move(twin, 90, 1.0);
    ASSERT_TRUE(o.done) << configured[i];
    for (int k = 0; k < 50; ++k) twin.run_cycle(); // 0.1 s after Done
    overshoot[i] = twin.moves()[0].overshoot_deg;
    lag[i] = twin.moves()[0].max_tracking_error_deg;
  }
  EXPECT_GT(overshoot[1], 2.0 * overshoot[0]) << overshoot[0] << " vs " << overshoot[1];
  EXPECT_GT(overshoot[1], 0.02);
  EXPECT_GT(lag[1], 2.0 * lag[0]) << lag[0] << " vs " << lag[1];
}

// servo.md "Gravity": a horizontal axis with an eccentric mass m at radius r
// needs m g r cos(angle) of holding torque; the drive's integral action
// finds it within what holds the flange without the motor: the rotor's
// breakaway friction (Coulomb + Stribeck excess, A-TWIN-22), the gear's
// load-dependent loss on the holding torque (A-TWIN-46) and cogging
// (A-TWIN-23), all from the card. The moves run at 50 % acceleration: at
// 100 % the planned torque (M) plus m g r exceeds the stage (issue 35's
// card has 0.57 N m at the flange).
TEST(TwinPhysics, HoldingTorqueFollowsMgrCosAngleOnAHorizontalAxis) {
  const double m = 0.2, r = 0.06;
  const double mgr = m * 9.81 * r;
  TwinConfig c;
  c.load = ArmLoad{m, r, 0.0};
  c.mounting_tilt_deg = 90.0;
  c.record_trace = false;
  Twin twin(c);
  const MechanicsConstants& k = c.module.mechanics;
  const double stiction_Nm = k.coulomb_friction_Nm + k.stribeck_excess_Nm + (1.0 - k.gear_efficiency) * mgr +
                             k.cogging_torque_Nm;
  ASSERT_GT(stiction_Nm, 0.0);
  ASSERT_LT(stiction_Nm, 0.25 * mgr); // the check below still sees gravity's cosine
  const uint16_t load = static_cast<uint16_t>(std::lround(twin.load_inertia_gcm2()));
  write_raw(twin, 64, 4, load); // the hold before the first move (A-SM-6)
  write_raw(twin, 65, 4, load);
  write_raw(twin, 65, 2, 500); // acceleration 50 %
  for (double deg : {45.0, 90.0, 0.0, -60.0}) {
    const Outcome o = move(twin, deg, 1.0);
    ASSERT_TRUE(o.done) << deg << " deg, error " << int{o.error_code};
    ProcessDataOut pd = twin.pd_out();
    pd.move = false;
    twin.set_pd_out(pd);
    for (int n = 0; n < 100; ++n) twin.run_cycle(); // 0.2 s holding
    EXPECT_NEAR(twin.plant().applied_torque_Nm(), -mgr * std::cos(deg_to_rad(deg)), stiction_Nm) << deg << " deg";
  }
}

// Manual 3.5.2 Fig. 3: settling runs from (b) to (f), never negative, and
// positioning = travel + settling; a move that trips SettlingTimeout (114.8)
// never completes and has no settling time.
TEST(TwinPhysics, MoveRecordsFollowFig3_3_5_2) {
  TwinConfig c;
  c.load = InertiaLoad{15000};
  c.record_trace = false;
  Twin twin(c);
  write_raw(twin, 65, 4, 15000);
  write_raw(twin, 65, 6, 50);   // waiting time 5 ms
  write_raw(twin, 65, 5, 146);  // 0.1 deg
  ASSERT_TRUE(move(twin, 90, 1.0).done);
  const MoveRecord loose = twin.moves()[0];
  EXPECT_TRUE(loose.completed());
  ASSERT_TRUE(loose.settling_s && loose.positioning_s);
  EXPECT_GE(*loose.settling_s, 0.005 - 1e-9); // at least the waiting time
  EXPECT_NEAR(*loose.positioning_s, loose.travel_s + *loose.settling_s, 1e-12);

  // A window of two encoder counts on the heaviest load: not held within
  // 2 ms (manual 3.5.8, 114.8).
  Twin tight(c);
  write_raw(tight, 65, 4, 15000);
  write_raw(tight, 65, 5, 2);   // 2 counts = 0.0014 deg
  write_raw(tight, 65, 6, 50);  // 5 ms
  write_raw(tight, 65, 7, 20);  // timeout 2 ms
  const Outcome o = move(tight, 90, 1.0);
  EXPECT_FALSE(o.done);
  EXPECT_EQ(o.error_code, 1u << 0) << int{o.error_code}; // bit 0: positioning error 114.8 (manual 2.4)
  ASSERT_EQ(tight.moves().size(), 1u);
  EXPECT_FALSE(tight.moves()[0].completed());
  EXPECT_FALSE(tight.moves()[0].settling_s.has_value()); // null: never completed
}

// Issue 14: a tighter window takes at least as long, a heavier load longer.
TEST(TwinPhysics, SettlingGrowsWithTighterWindowAndLoad_3_5_7) {
  auto settling = [](double load_gcm2, uint16_t tolerance_counts) {
    TwinConfig c;
    c.load = InertiaLoad{load_gcm2};
    c.record_trace = false;
    Twin twin(c);
    write_raw(twin, 65, 4, static_cast<uint16_t>(load_gcm2));
    write_raw(twin, 65, 5, tolerance_counts);
    write_raw(twin, 65, 6, 50); // 5 ms
    EXPECT_TRUE(move(twin, 90, 1.0).done) << load_gcm2 << ", " << tolerance_counts;
    return twin.moves().at(0).settling_s.value_or(-1.0);
  };
  const double heavy_tight = settling(15000, 15); // 0.01 deg
  const double heavy_loose = settling(15000, 146); // 0.1 deg
  const double light_loose = settling(100, 728);   // 0.5 deg
  EXPECT_GE(heavy_tight, heavy_loose);
  EXPECT_GE(heavy_tight, 2.0 * light_loose);
  EXPECT_GE(heavy_tight - 0.005, 0.001); // at least 1 ms beyond the waiting time
}

// Issue 14 done-when, manual 3.5.2 Fig. 3 / 3.5.7 with no waiting time:
// settling (from (b) to the first sample inside the window) grows with the
// load and with a tighter window, from the loop delays (A-CTRL-7) and the
// load's compliance (A-TWIN-20), never from an `if`. One 90 deg move per
// cell at 3000 deg/s, 100 %, 100 % (parameter set 1 defaults).
double settling_without_wait(double load_gcm2, double tolerance_deg) {
  TwinConfig c;
  c.load = InertiaLoad{load_gcm2};
  c.record_trace = false;
  Twin twin(c);
  write_raw(twin, 65, 4, static_cast<uint16_t>(load_gcm2));
  write_raw(twin, 65, 5, static_cast<uint16_t>(std::lround(tolerance_deg / 360.0 * 524288.0)));
  write_raw(twin, 65, 6, 0);     // no waiting time
  write_raw(twin, 65, 7, 10000); // settling timeout 1 s
  const Outcome o = move(twin, 90, 1.5);
  EXPECT_TRUE(o.done) << load_gcm2 << " g cm^2, " << tolerance_deg << " deg, error " << int{o.error_code};
  if (twin.moves().empty() || !twin.moves()[0].completed()) return -1.0;
  return twin.moves()[0].settling_s.value_or(-1.0);
}

TEST(TwinPhysics, SettlingNoWaitGrowsWithLoadAndTighterWindow_3_5_7) {
  const std::vector<double> loads{0, 1000, 5000, 10000, 15000};
  const std::vector<double> tolerances{1.0, 0.2, 0.05, 0.01}; // loosest first
  const double noise_s = 0.001;
  std::vector<std::vector<double>> t(loads.size(), std::vector<double>(tolerances.size()));
  for (std::size_t i = 0; i < loads.size(); ++i) {
    for (std::size_t j = 0; j < tolerances.size(); ++j) t[i][j] = settling_without_wait(loads[i], tolerances[j]);
  }
  for (std::size_t i = 0; i < loads.size(); ++i) {
    for (std::size_t j = 0; j < tolerances.size(); ++j) {
      EXPECT_GE(t[i][j], 0.0) << loads[i] << ", " << tolerances[j];
      if (i > 0) {
        EXPECT_GE(t[i][j], t[i - 1][j] - noise_s) << "heavier load, " << loads[i] << ", " << tolerances[j];
      }
      if (j > 0) {
        EXPECT_GE(t[i][j], t[i][j - 1] - noise_s) << "tighter window, " << loads[i] << ", " << tolerances[j];
      }
    }
  }
  // The heaviest load in the tightest window takes real time; the light
  // ones in a loose window are there at (b).
  EXPECT_GE(t.back().back(), 0.001);
  EXPECT_EQ(t.front().front(), 0.0);
}

TEST(TwinPhysics, HeavyTightSettlesTwiceAsLongAsLightLoose_3_5_7) {
  const double heavy_tight = settling_without_wait(15000, 0.01);
  const double light_loose = settling_without_wait(100, 0.5);
  EXPECT_GE(heavy_tight, 2.0 * light_loose);
  EXPECT_GE(heavy_tight, 0.001);
  EXPECT_GE(heavy_tight, settling_without_wait(15000, 0.1)); // 0.01 deg at least as long as 0.1 deg
}

// Manual 3.5.7 / 7.3 115.3 ("vibration ... especially in combination with
// large loads"): with no waiting time the heaviest load is found good in a
// 45-count (0.031 deg) window at the end of the trajectory, the flange's
// swing pulls the rotor out of it (71 counts past the target with the
// issue-35 card) and 115.3 follows; the rotor sticks there in the friction
// band until the integral breaks it loose, and is back ~0.13 s after the
// end of the trajectory: in_window_s records when it entered the window for
// good (servo.md). (The former 0.05 deg window is not left at this
// target, only at some a few counts away: the planetary's spring swings
// less; docs/settling.md.)
TEST(TwinPhysics, HeavyLoadLeavesWindowAfterDoneNoWait_3_5_7) {
  TwinConfig c;
  c.load = InertiaLoad{15000};
  c.record_trace = false;
  Twin twin(c);
  write_raw(twin, 65, 4, 15000);
  write_raw(twin, 65, 5, 45); // 0.0309 deg
  write_raw(twin, 65, 6, 0);  // no waiting time
  ASSERT_TRUE(move(twin, 90, 1.0).done);
  EXPECT_EQ(twin.moves()[0].settling_s.value_or(-1.0), 0.0);
  for (int k = 0; k < 150; ++k) twin.run_cycle(); // 0.3 s holding
  EXPECT_NE(twin.telemetry().warning_code, 0);
  EXPECT_GT(twin.moves()[0].overshoot_deg, 0.0309);
  EXPECT_GT(twin.moves()[0].in_window_s.value_or(0.0), 0.0);
}

// A window of a few encoder counts (3 counts = 0.002 deg) meets quantisation
// and friction inside the loop: late even with no load and no waiting time.
TEST(TwinPhysics, FewCountWindowSettlesLate_3_5_7) {
  const double few_counts_deg = 3 * 360.0 / 524288.0;
  EXPECT_GT(settling_without_wait(0, few_counts_deg), settling_without_wait(0, 0.5));
  EXPECT_GT(settling_without_wait(15000, few_counts_deg), 0.01);
}

} // namespace
} // namespace sreh
