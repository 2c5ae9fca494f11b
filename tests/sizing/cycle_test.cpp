// Multi-segment cycles (issue 17, `size --cycle`): the file, each segment
// sized with its own load, mounting, infeasible cycles naming their limit,
// and the emitted scenario passing in the twin. Given sets keep the runs
// short; one test recommends.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scenarios/runner.hpp"
#include "scenarios/scenario_parser.hpp"
#include "sizing/cycle.hpp"
#include "sizing/cycle_output.hpp"

namespace sreh::sizing {
namespace {

const std::string kData = std::string(SREH_SOURCE_DIR) + "/tests/sizing/data/";

CycleRequest from_text(const std::string& yaml) { return parse_cycle_text(yaml, "test.yaml", ""); }

std::string error_of(const std::string& file) {
  try {
    (void)parse_cycle_file(kData + "bad_cycles/" + file);
  } catch (const SizingInputError& e) {
    return e.what();
  }
  return "";
}

// Bad input: one error naming FILE:LINE:COL (style: exit 2 in the CLI).
TEST(CycleFile, BadFilesNameFileLineAndColumn) {
  const std::string dir = kData + "bad_cycles/";
  EXPECT_NE(error_of("unknown_key.yaml").find(dir + "unknown_key.yaml:3:"), std::string::npos) << error_of("unknown_key.yaml");
  EXPECT_NE(error_of("unknown_key.yaml").find("sped_dps"), std::string::npos);
  EXPECT_NE(error_of("two_kinds.yaml").find(dir + "two_kinds.yaml:4:5:"), std::string::npos) << error_of("two_kinds.yaml");
  EXPECT_NE(error_of("bad_load.yaml").find(dir + "bad_load.yaml:4:"), std::string::npos) << error_of("bad_load.yaml");
  EXPECT_NE(error_of("bad_load.yaml").find("radius_m"), std::string::npos);
  EXPECT_NE(error_of("voltage_40.yaml").find(dir + "voltage_40.yaml:2:"), std::string::npos) << error_of("voltage_40.yaml");
  EXPECT_NE(error_of("no_move.yaml").find("at least one move"), std::string::npos) << error_of("no_move.yaml");
  EXPECT_NE(error_of("syntax.yaml").find(dir + "syntax.yaml:"), std::string::npos) << error_of("syntax.yaml");
  EXPECT_NE(error_of("empty_segments.yaml").find(dir + "empty_segments.yaml:2:"), std::string::npos);
  // A set holds one configured load (64+n.4): used with two loads is refused with both places.
  const CycleRequest two = parse_cycle_file(dir + "set_two_loads.yaml");
  try {
    (void)plan_sets(two);
    FAIL() << "a set used with two loads was accepted";
  } catch (const SizingInputError& e) {
    EXPECT_NE(std::string(e.what()).find("set_two_loads.yaml:5:5: parameter set 2"), std::string::npos) << e.what();
  }
}

TEST(CycleFile, ReadsTheIssueShape) {
  const CycleRequest c = from_text(
      "mounting: {axis: horizontal}\n"
      "load: {arm: {mass_kg: 0.3, radius_m: 0.06}}\n"
      "supply: {voltage_V: 20, source_resistance_ohm: 0.5, bus_capacitance_F: 0.001}\n"
      "ambient_C: 35\n"
      "process_torque_Nm: 0.02\n"
      "segments:\n"
      "  - {move_deg: 90}\n"
      "  - {dwell_s: 0.2}\n"
      "  - {load: {inertia_gcm2: 4000}}\n"
      "  - {move_deg: -45, relative: true, parameter_set: 3, process_torque_Nm: 0.1}\n");
  EXPECT_EQ(c.world.mounting_tilt_deg, 90.0);
  EXPECT_TRUE(std::holds_alternative<ArmLoad>(c.world.load));
  EXPECT_EQ(c.world.supply.voltage_V, 20.0);
  EXPECT_EQ(c.world.supply.source_resistance_ohm, 0.5);
  EXPECT_EQ(c.world.thermal.ambient_C, 35.0);
  ASSERT_EQ(c.segments.size(), 4u);
  EXPECT_EQ(std::get<CycleMove>(c.segments[0].what).target_deg, 90.0);
  EXPECT_EQ(std::get<CycleDwell>(c.segments[1].what).dwell_s, 0.2);
  EXPECT_EQ(std::get<InertiaLoad>(std::get<CycleLoadChange>(c.segments[2].what).load).inertia_gcm2, 4000.0);
  const CycleMove& m = std::get<CycleMove>(c.segments[3].what);
  EXPECT_TRUE(m.relative);
  EXPECT_EQ(m.parameter_set, 3);
  EXPECT_EQ(m.process_torque_Nm, 0.1);
  EXPECT_EQ(c.segments[3].line, 10);
}

// Issue 17: a cycle with a load change sizes each segment with its own load:
// its own set (64+n.4 = that load) and the twin carrying that load.
TEST(CycleSize, LoadChangeSizesEachSegmentWithItsOwnLoad) {
  const CycleRequest rq = parse_cycle_file(kData + "load_change_cycle.yaml");
  const CycleResult r = size_cycle(rq);
  const CycleEvaluation& e = r.evaluation;
  ASSERT_TRUE(e.completed) << e.reason;
  ASSERT_EQ(e.sets.size(), 2u);
  EXPECT_EQ(e.sets[0].load_gcm2, 1000.0);
  EXPECT_EQ(e.sets[1].load_gcm2, 12000.0);
  ASSERT_EQ(e.segments.size(), 5u);
  const SegmentResult& light = e.segments[0];
  const SegmentResult& heavy = e.segments[3];
  EXPECT_EQ(light.kind, "move");
  EXPECT_EQ(e.segments[1].kind, "dwell");
  EXPECT_EQ(e.segments[2].kind, "load");
  EXPECT_EQ(heavy.kind, "move");
  EXPECT_EQ(light.parameter_set, e.sets[0].set);
  EXPECT_EQ(heavy.parameter_set, e.sets[1].set);
  EXPECT_NEAR(heavy.load_gcm2, 12000.0, 1.0); // MuJoCo's inertia about the axis during the move
  // The same speed, acceleration and jerk in %: alpha100% falls with the
  // configured load (manual 3.5.4), so the heavy move travels longer, and
  // it takes more torque to accelerate 12x the inertia.
  EXPECT_GT(heavy.travel_s, light.travel_s * 1.1);
  EXPECT_GT(heavy.positioning_s, light.positioning_s * 1.1);
  EXPECT_GT(heavy.rms_torque_Nm, light.rms_torque_Nm * 1.2);
  // Segment durations: moves = positioning + handshake, dwells as given, load changes 0.
  EXPECT_DOUBLE_EQ(light.duration_s, light.positioning_s + e.handshake_s);
  EXPECT_DOUBLE_EQ(e.segments[1].duration_s, 0.05);
  EXPECT_EQ(e.segments[2].duration_s, 0.0);
  double sum = 0;
  for (const SegmentResult& s : e.segments) sum += s.duration_s;
  EXPECT_DOUBLE_EQ(e.cycle_s, sum);
  EXPECT_EQ(e.handshake_s, 4 * 0.002); // A-SIZE-16

  // The flange really carried each load (the twin's MuJoCo model, rebuilt
  // at the load change, A-TWIN-33; tests/twin/plant_load_test.cpp).
  EXPECT_NEAR(light.load_gcm2, 1000.0, 1.0);
}

// Issue 17: a horizontal axis with an eccentric arm needs more torque than
// the vertical one (gravity, A-TWIN-24), in a cycle as for a single move.
TEST(CycleSize, HorizontalEccentricArmNeedsMoreTorqueThanVertical) {
  const std::string body =
      "load: {arm: {mass_kg: 0.3, radius_m: 0.06}}\n"
      "segments:\n"
      "  - {move_deg: 90, speed_dps: 600, accel_pct: 50, jerk_pct: 100}\n"
      "  - {dwell_s: 0.1}\n"
      "  - {move_deg: 0, speed_dps: 600, accel_pct: 50, jerk_pct: 100}\n"
      "  - {dwell_s: 0.3}\n"; // the gripper works with the arm level
  const CycleResult vertical = size_cycle(from_text("mounting: {axis: vertical}\n" + body));
  const CycleResult horizontal = size_cycle(from_text("mounting: {axis: horizontal}\n" + body));
  ASSERT_TRUE(vertical.evaluation.completed) << vertical.evaluation.reason;
  ASSERT_TRUE(horizontal.evaluation.completed) << horizontal.evaluation.reason;
  // Holding the arm level against gravity: m g r = 0.3 x 9.81 x 0.06 = 0.18 N m at 0 deg.
  EXPECT_GT(horizontal.evaluation.rms_torque_Nm, vertical.evaluation.rms_torque_Nm * 1.2);
  EXPECT_GT(horizontal.evaluation.peak_torque_Nm, vertical.evaluation.peak_torque_Nm);
  EXPECT_GT(horizontal.evaluation.utilisation.rms_torque_pct, vertical.evaluation.utilisation.rms_torque_pct);
  EXPECT_NEAR(horizontal.evaluation.segments[3].hold_rms_torque_Nm, 0.3 * 9.81 * 0.06, 0.02);
  EXPECT_LT(vertical.evaluation.segments[3].hold_rms_torque_Nm, 0.02);
}

// Infeasible cycles name the limit that failed (A-SIZE-5), the same checks
// as a single move.
TEST(CycleSize, InfeasibleCyclesNameTheirBindingLimit) {
  CycleRequest rq = parse_cycle_file(kData + "process_torque_too_high.yaml");
  const CycleResult torque = size_cycle(rq);
  EXPECT_FALSE(torque.evaluation.feasible);
  EXPECT_TRUE(torque.evaluation.completed);
  EXPECT_EQ(torque.evaluation.binding_limit, "torque_at_speed") << torque.evaluation.reason;
  EXPECT_GT(torque.evaluation.peak_torque_Nm, kTorqueMargin * torque.evaluation.torque_capability_Nm);
  rq.process_torque_Nm = 0.1; // the process torque is what makes the difference
  const CycleResult lighter = size_cycle(rq);
  EXPECT_TRUE(lighter.evaluation.feasible) << lighter.evaluation.reason;
  EXPECT_LT(lighter.evaluation.peak_torque_Nm, torque.evaluation.peak_torque_Nm - 0.04);
  // Manual 3.5.3: 4300 deg/s is out of reach at 16 V: the motor cannot
  // follow and the device's monitor ends the move (114.5).
  const CycleResult volts = size_cycle(parse_cycle_file(kData + "low_voltage_fast.yaml"));
  EXPECT_FALSE(volts.evaluation.feasible);
  EXPECT_FALSE(volts.evaluation.completed);
  EXPECT_EQ(volts.evaluation.binding_limit, "tracking") << volts.evaluation.reason;
  const nlohmann::json j = cycle_to_json(parse_cycle_file(kData + "low_voltage_fast.yaml"), volts);
  EXPECT_EQ(j["feasible"], false);
  EXPECT_EQ(j["binding_limit"], "tracking");
  EXPECT_TRUE(j["cycle_s"].is_null());
}

// Without sets in the file a set per load is recommended (A-SIZE-20), and
// the result is feasible with every margin.
TEST(CycleSize, RecommendsASetPerLoad) {
  const CycleResult r = size_cycle(from_text("load: {inertia_gcm2: 500}\n"
                                             "segments:\n"
                                             "  - {move_deg: 45}\n"
                                             "  - {load: {inertia_gcm2: 3000}}\n"
                                             "  - {move_deg: 0}\n"
                                             "  - {dwell_s: 0.3}\n"));
  EXPECT_TRUE(r.recommended);
  ASSERT_TRUE(r.evaluation.feasible) << r.evaluation.reason;
  ASSERT_EQ(r.evaluation.sets.size(), 2u);
  EXPECT_EQ(r.evaluation.sets[0].set, 1);
  EXPECT_EQ(r.evaluation.sets[1].set, 2);
  EXPECT_GT(r.simulations, 1);
  const nlohmann::json j = cycle_to_json(from_text("load: {inertia_gcm2: 500}\nsegments: [{move_deg: 45}]\n"), r);
  for (const char* key : {"segments", "cycle_s", "utilisation", "supply", "binding_limit", "feasible", "sets"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  for (const char* key : {"peak_torque_pct", "rms_torque_pct", "thermal_margin_K"}) EXPECT_TRUE(j["utilisation"].contains(key));
  for (const char* key : {"peak_current_A", "rms_current_A", "regen_energy_J", "peak_bus_V"}) EXPECT_TRUE(j["supply"].contains(key));
  for (const char* key : {"kind", "duration_s", "travel_s", "settling_s", "positioning_s", "peak_torque_Nm", "rms_torque_Nm"}) {
    EXPECT_TRUE(j["segments"][0].contains(key)) << key;
  }
}

// Issue 17 hand-over: the emitted scenario replays the cycle in the twin and passes.
TEST(CycleScenario, EmittedScenarioPassesInTheTwin) {
  const CycleRequest rq = parse_cycle_file(kData + "load_change_cycle.yaml");
  const CycleResult r = size_cycle(rq);
  ASSERT_TRUE(r.evaluation.completed) << r.evaluation.reason;
  const CyclePlan plan = plan_sets(rq);
  std::vector<int> set_of_segment;
  for (int k : plan.move_set) set_of_segment.push_back(k < 0 ? -1 : plan.sets[static_cast<std::size_t>(k)].set);
  const std::string yaml = scenario_yaml(rq, r.evaluation.sets, set_of_segment, "load change cycle");
  EXPECT_NE(yaml.find("- load: {inertia_gcm2: 12000}"), std::string::npos) << yaml;
  const Scenario sc = parse_scenario_text(yaml, "emitted.yaml", "");
  const RunResult run = run_scenario(sc);
  EXPECT_TRUE(run.passed) << yaml << (run.failures.empty() ? "" : run.failures.front());
  EXPECT_EQ(run.moves.size(), 2u * static_cast<std::size_t>(rq.cycles));
}

} // namespace
} // namespace sreh::sizing
