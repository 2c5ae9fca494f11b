// Sizing (issue 8, manual 3.5.1 PerfectCycle): evaluation of a given set,
// the recommendation, refusals. Short moves and one or two cycles keep the
// runtime small.
#include <gtest/gtest.h>

#include "scenarios/scenario_parser.hpp"

#include <string>

#include "device_logic/motor_model.hpp"
#include "device_logic/parameter_table.hpp"
#include "device_logic/planner.hpp"
#include "device_logic/units.hpp"
#include "sizing/output.hpp"
#include "sizing/sizing.hpp"
#include "sizing/thermal_estimate.hpp"
#include "twin/twin.hpp"

namespace sreh::sizing {
namespace {

SizingRequest request(double angle_deg, double load_gcm2, std::optional<MotionSetting> setting, int cycles = 1) {
  SizingRequest rq;
  rq.angle_deg = angle_deg;
  rq.world.load = InertiaLoad{load_gcm2};
  rq.setting = setting;
  rq.cycles = cycles;
  return rq;
}

// Manual 3.5.2 (1): the travel time is the duration of the target
// trajectory, i.e. the time-optimal S-curve for the set's limits.
TEST(Size, ExplicitSetTravelTimeIsThePlannersExactly_3_5_2) {
  const SizingResult r = size(request(90.0, 1000.0, MotionSetting{1500.0, 60.0, 40.0}));
  const Evaluation& e = r.evaluation;
  EXPECT_FALSE(r.recommended);
  EXPECT_EQ(r.simulations, 1);
  EXPECT_EQ(e.set.setting.speed_dps, 1500.0);
  EXPECT_EQ(e.set.setting.accel_pct, 60.0);
  EXPECT_EQ(e.set.setting.jerk_pct, 40.0);
  EXPECT_EQ(e.set.load_gcm2, 1000.0);
  const Profile p = Profile::rest_to_rest(kPi / 2, limits_from_parameter_set(1500.0, 60.0, 40.0, 1000.0));
  EXPECT_EQ(e.travel_s, p.duration_s());
  ASSERT_EQ(e.moves.size(), 2u);
  for (const MoveResult& m : e.moves) {
    EXPECT_EQ(m.travel_s, p.duration_s());
    // The simulation runs on the 0.1 ms step clock (A-TWIN-12).
    EXPECT_NEAR(m.simulated_travel_s, p.duration_s(), 1e-4 + 1e-9);
  }
}

// Manual 3.5.2 (2), (4): settling and positioning come from the simulation;
// positioning = travel + settling.
TEST(Size, SettlingAndPositioningFromSimulationAreConsistent_3_5_2) {
  const SizingResult r = size(request(45.0, 3000.0, MotionSetting{2000.0, 80.0, 80.0}, 2));
  const Evaluation& e = r.evaluation;
  ASSERT_TRUE(e.feasible) << e.reason;
  EXPECT_TRUE(e.completed);
  ASSERT_EQ(e.moves.size(), 4u); // 2 cycles back and forth
  for (const MoveResult& m : e.moves) {
    EXPECT_TRUE(m.completed);
    EXPECT_GT(m.settling_s, 0.0);
    EXPECT_GT(m.positioning_s, m.travel_s);
    EXPECT_NEAR(m.positioning_s, m.travel_s + m.settling_s, 1e-12);
    EXPECT_LE(m.settling_s, e.set.timeout_ms * 1e-3); // manual 3.5.8: no timeout
  }
  EXPECT_NEAR(e.positioning_s, e.travel_s + e.settling_s, 1e-12);
  // No dwell; the PLC handshake, 4 IO-Link cycles of 2 ms per move (A-SIZE-16).
  EXPECT_DOUBLE_EQ(e.handshake_s, 4 * 0.002);
  EXPECT_DOUBLE_EQ(e.cycle_s, 2 * (e.positioning_s + e.handshake_s));
  EXPECT_DOUBLE_EQ(e.cycles_per_min, 60.0 / e.cycle_s);
  EXPECT_GT(e.peak_torque_Nm, 0.0);
  EXPECT_GT(e.rms_torque_Nm, 0.0);
  EXPECT_LE(e.rms_torque_Nm, e.peak_torque_Nm);
  EXPECT_EQ(e.torque_capability_Nm, default_module_model().drive.motor.peak_torque_Nm());
  EXPECT_GT(e.steady_temperature_C, 25.0);
}

// A dwell lengthens the cycle and cools the module (manual 7.2 114.3:
// "longer pauses between movements").
TEST(Size, DwellLengthensTheCycleAndLowersTheTemperature) {
  SizingRequest busy = request(45.0, 3000.0, MotionSetting{2000.0, 80.0, 80.0});
  SizingRequest calm = busy;
  calm.dwell_s = 1.0;
  const Evaluation a = size(busy).evaluation;
  const Evaluation b = size(calm).evaluation;
  EXPECT_NEAR(b.cycle_s, 2 * (b.positioning_s + b.handshake_s) + 2.0, 1e-12);
  EXPECT_LT(b.mean_loss_W, a.mean_loss_W);
  EXPECT_LT(b.steady_temperature_C, a.steady_temperature_C);
  EXPECT_LT(b.rms_torque_Nm, a.rms_torque_Nm);
}

// Manual 3.5.3: at 16 V the reachable speed is about 4300 x 16 / 24; the
// full 4300 deg/s ends in a position tracking error (114.5): infeasible.
TEST(Size, TooFastForTheVoltageIsInfeasible_3_5_3) {
  SizingRequest rq = request(360.0, 0.0, MotionSetting{4300.0, 100.0, 100.0});
  rq.world.supply.voltage_V = 16.0;
  const Evaluation e = size(rq).evaluation;
  EXPECT_FALSE(e.feasible);
  EXPECT_FALSE(e.completed);
  EXPECT_NE(e.reason.find("tracking error (114.5)"), std::string::npos) << e.reason;
  // Below the factory window of index 85 (18 V) the set widens it.
  bool widened = false;
  for (const IsduWrite& w : e.set.writes) widened |= w.index == 85 && w.subindex == 1 && w.value == 16000;
  EXPECT_TRUE(widened);
}

// The recommendation is verified the way a PLC would use it: a fresh twin,
// the printed ISDU writes, Motor On, the moves; each must reach Done.
// 180 deg with 15000 g cm^2 and no dwell at 100 % settles ~11 K above the
// room (docs/model-card.md "Thermal steady state"): on a 50 degC machine
// with a 10 K margin (steady at most 60 degC) that is too hot, so the
// search has to back off from its first try, and the set it finds is then
// run in a twin at 50 degC.
TEST(Size, RecommendedSetRunsInTheTwinWithoutError) {
  SizingRequest rq = request(180.0, 15000.0, std::nullopt);
  rq.world.thermal.ambient_C = 50.0;
  rq.thermal_margin_K = 10.0;
  const SizingResult r = size(rq);
  const Evaluation& e = r.evaluation;
  ASSERT_TRUE(r.recommended);
  ASSERT_TRUE(e.feasible) << e.reason;
  EXPECT_LT(e.steady_temperature_C, kTemperatureWarning_C);
  EXPECT_FALSE(e.time_to_warning_s.has_value());
  EXPECT_LE(e.peak_torque_Nm, kTorqueMargin * e.torque_capability_Nm);
  EXPECT_LE(r.simulations, 60); // A-SIZE-10's bound
  // The search must have backed off from an infeasible first try.
  ASSERT_FALSE(r.tried.empty());
  EXPECT_FALSE(r.tried.front().feasible);
  EXPECT_TRUE(e.set.setting.accel_pct < 100.0 || e.set.setting.jerk_pct < 100.0 ||
              e.set.setting.speed_dps < max_speed_dps());
  EXPECT_LE(e.steady_temperature_C, kTemperatureWarning_C - 10.0); // the requested margin
  EXPECT_EQ(e.set.load_gcm2, 15000.0);

  TwinConfig cfg;
  cfg.load = InertiaLoad{15000.0};
  cfg.thermal.ambient_C = 50.0;
  Twin twin(cfg);
  for (const IsduWrite& w : e.set.writes) {
    const ParameterEntry* row = find_parameter(w.index, w.subindex);
    ASSERT_NE(row, nullptr);
    ASSERT_TRUE(twin.isdu_write(w.index, w.subindex, encode_number(row->type, w.value)).ok()) << w.index;
  }
  ProcessDataOut pd;
  pd.motor_on = true;
  pd.parameter_set = 1;
  twin.set_pd_out(pd);
  for (int i = 0; i < 10; ++i) twin.run_cycle();
  ASSERT_TRUE(twin.pd_in().ready);
  for (double target : {180.0, 0.0}) {
    pd.target_raw = static_cast<int32_t>(deg_to_wire_counts(target));
    pd.move = true;
    twin.set_pd_out(pd);
    int cycles = 0;
    while (!twin.pd_in().done && !twin.pd_in().error && cycles++ < 1000) twin.run_cycle();
    ASSERT_TRUE(twin.pd_in().done) << "to " << target;
    EXPECT_EQ(twin.pd_in().error_code, 0);
    EXPECT_EQ(twin.pd_in().warning_code, 0);
    EXPECT_NEAR(twin.telemetry().position_deg, target, e.set.tolerance_deg);
    pd.move = false;
    twin.set_pd_out(pd);
    twin.run_cycle();
  }
  ASSERT_EQ(twin.moves().size(), 2u);
  for (const MoveRecord& m : twin.moves()) EXPECT_NEAR(m.positioning_s.value_or(-1.0), e.positioning_s, 0.003);
}

// A move that is feasible at 100 %/100 % and the voltage's top speed needs
// little search; a speed the move never reaches is recommended as the
// lowest grid speed above its peak (the same trajectory, A-SIZE-10).
TEST(Size, FeasibleAtFullLimitsNeedsFewSimulations_3_5_3) {
  SizingRequest rq = request(30.0, 500.0, std::nullopt);
  rq.dwell_s = 0.5;
  rq.world.supply.voltage_V = 19.0;
  const SizingResult r = size(rq);
  ASSERT_TRUE(r.evaluation.feasible) << r.evaluation.reason;
  EXPECT_LE(r.simulations, 3);
  EXPECT_EQ(r.binding_limit, "module_limits");
  const MotionSetting& s = r.evaluation.set.setting;
  EXPECT_EQ(s.accel_pct, 100.0);
  EXPECT_EQ(s.jerk_pct, 100.0);
  const MotionLimits top = limits_from_parameter_set(4300.0 * 19.0 / 24.0, 100.0, 100.0, 500.0);
  const MotionLimits rec = limits_from_parameter_set(s.speed_dps, 100.0, 100.0, 500.0);
  EXPECT_NEAR(r.evaluation.travel_s, Profile::rest_to_rest(kPi / 6, top).duration_s(), 1e-5); // 30 deg in wire counts
  EXPECT_LE(std::abs(Profile::rest_to_rest(kPi / 6, rec).peak_velocity_rad_s()), rec.v_max_rad_s);
}

// Manual 6.2 ranges and the module's limits: refused before any simulation.
TEST(Size, RefusesInputsOutsideTheModulesLimits_6_2) {
  EXPECT_THROW(size(request(90.0, 20000.0, std::nullopt)), SizingInputError); // 64.4: <= 15000 g cm^2
  SizingRequest volts = request(90.0, 2000.0, std::nullopt);
  volts.world.supply.voltage_V = 40.0; // index 85: 16..32 V
  EXPECT_THROW(size(volts), SizingInputError);
  volts.world.supply.voltage_V = 15.9;
  EXPECT_THROW(size(volts), SizingInputError);
  EXPECT_THROW(size(request(0.0, 2000.0, std::nullopt)), SizingInputError);
  EXPECT_THROW(size(request(5000.0, 2000.0, std::nullopt)), SizingInputError);
  SizingRequest dwell = request(90.0, 2000.0, std::nullopt);
  dwell.dwell_s = -0.1;
  EXPECT_THROW(size(dwell), SizingInputError);
  EXPECT_THROW(size(request(90.0, 2000.0, MotionSetting{4300.1, 100, 100})), SizingInputError);
  EXPECT_THROW(size(request(90.0, 2000.0, MotionSetting{1000, 0.0, 100})), SizingInputError);
  EXPECT_THROW(size(request(90.0, 2000.0, MotionSetting{1000, 100, 100.5})), SizingInputError);
  SizingRequest heavy;
  heavy.angle_deg = 90;
  heavy.world.load = DiskLoad{1.0, 0.2}; // 200000 g cm^2 as MuJoCo computes it
  EXPECT_THROW(size(heavy), SizingInputError);
  EXPECT_THROW(validate(heavy), std::invalid_argument); // InputError-like: a std::invalid_argument
}

// The set written is the raw wire encoding (manual 6.2, index 64+n).
TEST(ParameterSet, RawWritesForIndex65) {
  SizingRequest rq = request(90.0, 0.0, std::nullopt);
  rq.world.supply.voltage_V = 31.0;
  const ParameterSetValues v = make_parameter_set(rq, MotionSetting{3000.0, 50.0, 25.5}, 2000.4);
  ASSERT_EQ(v.writes.size(), 9u);
  EXPECT_EQ(v.writes[0].index, 65);
  EXPECT_EQ(v.writes[0].value, 30000); // 0.1 deg/s
  EXPECT_EQ(v.writes[1].value, 500);   // 0.1 %
  EXPECT_EQ(v.writes[2].value, 255);
  EXPECT_EQ(v.writes[3].value, 2000);  // g cm^2
  EXPECT_EQ(v.writes[4].value, 146);   // 0.1 deg in 2^-19 rev (factory default)
  EXPECT_EQ(v.writes[5].value, 250);   // 25 ms in 0.1 ms
  EXPECT_EQ(v.writes[6].value, 1000);  // A-SIZE-4: 100 ms for the 25 ms wait
  EXPECT_EQ(v.writes[7].value, 1);
  EXPECT_EQ(v.writes[8].index, 85);    // 31 V is above the factory 30 V maximum
  EXPECT_EQ(v.writes[8].subindex, 2);
  EXPECT_EQ(v.writes[8].value, 32000);
  EXPECT_EQ(isdu_write_line(v.writes[0]), "- isdu_write: {index: 65, subindex: 1, value: 30000}  # speed 3000.0 deg/s");
}

// The printed writes paste into a scenario as they are (issue 16): every line
// parses as an isdu_write step with the same index, subindex and raw value.
TEST(ParameterSet, IsduWriteLinesAreScenarioSteps) {
  SizingRequest rq;
  rq.world.supply.voltage_V = 17.0; // adds the 85.1 window write
  const ParameterSetValues v = make_parameter_set(rq, MotionSetting{1234.5, 40.0, 12.5}, 3000.0);
  std::string yaml = "name: pasted from size\nsteps:\n";
  for (const IsduWrite& w : v.writes) yaml += "  " + isdu_write_line(w) + "\n";
  const Scenario sc = parse_scenario_text(yaml, "pasted.yaml", "");
  ASSERT_EQ(sc.steps.size(), v.writes.size());
  for (std::size_t i = 0; i < v.writes.size(); ++i) {
    const auto* step = std::get_if<IsduWriteStep>(&sc.steps[i].action);
    ASSERT_NE(step, nullptr);
    EXPECT_EQ(step->index, v.writes[i].index);
    EXPECT_EQ(step->subindex, v.writes[i].subindex);
    EXPECT_EQ(decode_number(find_parameter(step->index, step->subindex)->type, step->data), v.writes[i].value);
  }
}

TEST(ParameterSet, TopSpeedFallsWithVoltage_3_5_3) {
  EXPECT_DOUBLE_EQ(voltage_speed_limit_dps(24.0), 4300.0);
  EXPECT_DOUBLE_EQ(voltage_speed_limit_dps(32.0), 4300.0);
  EXPECT_DOUBLE_EQ(voltage_speed_limit_dps(18.0), 4300.0 * 18.0 / 24.0);
}

// Manual 7.3 115.1: warning at 70 degC; the steady state of the twin's
// lumped model (A-TWIN-THERMAL-1: winding-to-housing and housing-to-ambient
// in series, 3 + 6 K/W with the issue-35 card, so 70 degC from 25 degC
// needs 5.0 W).
TEST(Thermal, SteadyStateAndTimeToWarning_7_3) {
  const ThermalConstants& k = default_module_model().thermal;
  const double series_K_per_W = k.winding_to_housing_K_per_W + k.housing_to_ambient_K_per_W;
  const ThermalEstimate cool = estimate_thermal(0.5, 25.0, k);
  EXPECT_NEAR(cool.steady_C, 25.0 + 0.5 * series_K_per_W, 1e-9);
  EXPECT_FALSE(cool.time_to_warning_s.has_value());
  const double warning_W = 45.0 / series_K_per_W;
  const ThermalEstimate hot = estimate_thermal(1.06 * warning_W, 25.0, k);
  ASSERT_TRUE(hot.time_to_warning_s.has_value());
  const ThermalEstimate hotter = estimate_thermal(1.5 * warning_W, 25.0, k);
  ASSERT_TRUE(hotter.time_to_warning_s.has_value());
  EXPECT_LT(*hotter.time_to_warning_s, *hot.time_to_warning_s);
  EXPECT_GT(*hot.time_to_warning_s, 60.0); // minutes, not seconds: the housing stores heat
}

TEST(Output, JsonHoldsTheInterfaceKeys) {
  const SizingRequest rq = request(30.0, 1000.0, MotionSetting{1000.0, 100.0, 100.0});
  const SizingResult r = size(rq);
  const nlohmann::json j = to_json(rq, r);
  for (const char* key : {"travel_s", "settling_s", "positioning_s", "cycle_s", "cycles_per_min", "peak_torque_Nm",
                          "rms_torque_Nm", "torque_capability_Nm", "steady_temperature_C", "time_to_warning_s",
                          "feasible", "reason", "recommended"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  for (const char* key : {"speed_dps", "accel_pct", "jerk_pct", "load_gcm2", "tolerance_deg", "wait_ms", "timeout_ms",
                          "isdu_writes"}) {
    EXPECT_TRUE(j["recommended"].contains(key)) << key;
  }
  EXPECT_TRUE(j["time_to_warning_s"].is_null());
  EXPECT_EQ(j["recommended"]["isdu_writes"].size(), 8u);
}

} // namespace
} // namespace sreh::sizing
