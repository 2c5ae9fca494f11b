// The scenario step `load:` (A-TWIN-33): another load on the flange from
// that step on, parsed with the same keys as the top-level load, and run:
// the twin then carries it.
#include <gtest/gtest.h>

#include <string>

#include "scenarios/runner.hpp"
#include "scenarios/scenario_parser.hpp"

namespace sreh {
namespace {

TEST(LoadStep, ParsesLikeTheTopLevelLoadAndNamesBadKeys) {
  const Scenario s = parse_scenario_text("name: grip\n"
                                         "steps:\n"
                                         "  - load: {arm: {mass_kg: 0.2, radius_m: 0.05}}\n"
                                         "  - load: {none: true}\n",
                                         "grip.yaml", "");
  ASSERT_EQ(s.steps.size(), 2u);
  const auto& arm = std::get<ArmLoad>(std::get<LoadStep>(s.steps[0].action).load);
  EXPECT_DOUBLE_EQ(arm.mass_kg, 0.2);
  EXPECT_TRUE(std::holds_alternative<NoLoad>(std::get<LoadStep>(s.steps[1].action).load));
  try {
    (void)parse_scenario_text("name: bad\nsteps:\n  - load: {disc: {mass_kg: 1}}\n", "bad.yaml", "");
    FAIL() << "an unknown load kind was accepted";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.yaml:3:"), std::string::npos) << e.what();
  }
}

// The same external torque turns a heavier flange more slowly once the
// load step has run (motor off, the flange free).
TEST(LoadStep, TheTwinCarriesTheNewLoad) {
  auto speed_after = [](const std::string& load_step) {
    const Scenario s = parse_scenario_text("name: push\nload: {inertia_gcm2: 1000}\nsteps:\n" + load_step +
                                               "  - torque: {Nm: 0.05, for_s: 0.02}\n",
                                           "push.yaml", "");
    RunOptions o;
    o.record_trace = true;
    const RunResult r = run_scenario(s, o);
    return r.trace.back().velocity_dps;
  };
  const double light = speed_after("");
  const double heavy = speed_after("  - load: {inertia_gcm2: 9000}\n");
  EXPECT_GT(light, 0.0);
  EXPECT_GT(light, 3.0 * heavy); // about 7x the inertia with J_intern
  EXPECT_GT(heavy, 0.0);
}

} // namespace
} // namespace sreh
