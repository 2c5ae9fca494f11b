// Runner semantics (scenarios/README.md "Timing"): steps on IO-Link cycle
// boundaries, checks recorded with step and line, bounded waits.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "scenarios/result_json.hpp"
#include "scenarios/runner.hpp"
#include "scenarios/scenario_parser.hpp"

namespace sreh {
namespace {

RunResult run_text(const std::string& text, const RunOptions& options = {}) {
  return run_scenario(parse_scenario_text(text, "t.yaml", ""), options);
}

TEST(ScenarioRunner, WaitStepsRoundUpToWholeCycles) {
  const RunResult r = run_text("name: x\nsteps:\n  - wait_s: 0.003\n  - wait_s: 0.004\n");
  EXPECT_EQ(r.cycles, 2u + 2u); // 2 ms IO-Link cycles (manual 1)
  EXPECT_TRUE(r.passed);
}

TEST(ScenarioRunner, PdStepLastsOneCycleAndKeepsOtherFields) {
  ProcessDataOut last{};
  RunOptions o;
  o.on_cycle = [&](const Twin& twin) { last = twin.pd_out(); };
  const RunResult r = run_text("name: x\nsteps:\n  - pd: {target_deg: 90, parameter_set: 3}\n  - pd: {relative: 1}\n", o);
  EXPECT_EQ(r.cycles, 2u);
  EXPECT_EQ(last.target_raw, 16384);
  EXPECT_EQ(last.parameter_set, 3);
  EXPECT_TRUE(last.relative);
  EXPECT_FALSE(last.motor_on);
}

TEST(ScenarioRunner, UnmetWaitUntilFailsAfterItsLimitAndTheRunGoesOn) {
  // Without motor_on the module stays in Motor Off (manual 3.2): Busy never comes.
  const RunResult r = run_text(R"(name: x
steps:
  - wait_until: {state: Busy, within_s: 0.1}
  - expect: {state: MotorOff}
)");
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.cycles, 50u);
  ASSERT_EQ(r.checks.size(), 2u);
  EXPECT_FALSE(r.checks[0].passed);
  EXPECT_TRUE(r.checks[1].passed); // the run went on
  ASSERT_EQ(r.failures.size(), 1u);
  EXPECT_NE(r.failures[0].find("step 1 (line 3)"), std::string::npos) << r.failures[0];
  EXPECT_NE(r.failures[0].find("state MotorOff (want Busy)"), std::string::npos) << r.failures[0];
}

TEST(ScenarioRunner, StopOnFailureEndsTheRun) {
  const RunResult r = run_text(R"(name: x
stop_on_failure: true
steps:
  - expect: {state: Done}
  - wait_s: 1
)");
  EXPECT_FALSE(r.passed);
  EXPECT_TRUE(r.stopped_early);
  EXPECT_EQ(r.cycles, 0u);
}

TEST(ScenarioRunner, TorqueForLastsItsDuration) {
  const RunResult r = run_text("name: x\nsteps:\n  - torque: {Nm: 0.01, for_s: 0.02}\n");
  EXPECT_EQ(r.cycles, 10u);
}

TEST(ScenarioRunner, LinkDownLastsItsDuration) {
  const RunResult r = run_text("name: x\nsteps:\n  - link: {down_s: 0.05}\n  - expect: {state: MotorOff, error: 0}\n");
  EXPECT_EQ(r.cycles, 26u); // 25 cycles down, then the master's first exchange (link back up)
  // manual 5: with the motor off a connection loss is no error.
  EXPECT_TRUE(r.passed) << (r.failures.empty() ? "" : r.failures[0]);
}

TEST(ScenarioRunner, IsduErrorPathsAreCheckable) {
  // iolink.md: 0x8011 index not available.
  const RunResult r = run_text("name: x\nsteps:\n  - isdu_read: {index: 4711, expect_error: 0x8011}\n"
                          "  - isdu_write: {index: 4711, value: 1, expect_error: 0x8011}\n");
  EXPECT_TRUE(r.passed) << (r.failures.empty() ? "" : r.failures[0]);
}

TEST(ScenarioRunner, UnexpectedIsduErrorFails) {
  const RunResult r = run_text("name: x\nsteps:\n  - isdu_read: {index: 4711}\n");
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.failures.at(0).find("0x8011"), std::string::npos) << r.failures[0];
}

TEST(ScenarioRunner, RepeatRunsItsStepsTimes) {
  const RunResult r = run_text("name: x\nsteps:\n  - repeat: {times: 4, steps: [{wait_s: 0.002}, {expect: {state: MotorOff}}]}\n");
  EXPECT_EQ(r.cycles, 4u);
  EXPECT_EQ(r.checks.size(), 4u);
}

TEST(ScenarioRunner, RepeatUntilStopsEarly) {
  // Pass 1 switches the motor on; `until` (Ready) then holds and ends the loop.
  const RunResult r = run_text("name: x\nsteps:\n  - repeat: {times: 50, until: {state: Ready}, steps: [{pd: {motor_on: 1}}, "
                          "{wait_s: 0.01}]}\n");
  EXPECT_EQ(r.cycles, 6u);
  EXPECT_TRUE(r.passed);
}

TEST(ScenarioRunner, NvmImageCarriesConfigurationIntoTheNextRun) {
  // interfaces.md: each run starts factory-new unless it names a saved image.
  const RunResult first = run_text("name: x\nsteps:\n  - isdu_write: {index: 82, value: 1}\n");
  const std::string path = ::testing::TempDir() + "scenarios_runner_test.nvm";
  {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(first.nvm_image.data()), static_cast<std::streamsize>(first.nvm_image.size()));
  }
  const RunResult second =
      run_text("name: x\ndevice: {nvm_image: " + path + "}\nsteps:\n  - isdu_read: {index: 82, expect: 1}\n");
  EXPECT_TRUE(second.passed) << (second.failures.empty() ? "" : second.failures[0]);
  const RunResult fresh = run_text("name: x\nsteps:\n  - isdu_read: {index: 82, expect: 0}\n");
  EXPECT_TRUE(fresh.passed);
  std::remove(path.c_str());
}

TEST(ScenarioRunner, JsonHoldsTheInterfaceKeys) {
  const RunResult r = run_text("name: x\nsteps:\n  - wait_s: 0.01\n");
  const nlohmann::json j = to_json(r);
  for (const char* key : {"passed", "failures", "moves", "final", "checks"}) EXPECT_TRUE(j.contains(key)) << key;
  for (const char* key : {"state", "position_deg", "error_code", "warning_code"}) EXPECT_TRUE(j["final"].contains(key)) << key;
  EXPECT_EQ(j["final"]["state"], "MotorOff");
}

TEST(ScenarioRunner, RunsAreDeterministic) {
  // docs/style.md 8/9: same scenario, same result.
  const std::string text = R"(name: x
load: {inertia_gcm2: 2000}
steps:
  - pd: {motor_on: 1}
  - wait_s: 0.05
  - pd: {target_deg: 45, parameter_set: 1, move: 1}
  - wait_s: 0.3
)";
  RunOptions o;
  o.record_trace = true;
  const RunResult a = run_text(text, o);
  const RunResult b = run_text(text, o);
  ASSERT_EQ(a.trace.size(), b.trace.size());
  for (std::size_t i = 0; i < a.trace.size(); ++i) {
    ASSERT_EQ(a.trace[i].position_deg, b.trace[i].position_deg) << "row " << i;
  }
}

} // namespace
} // namespace sreh

namespace sreh {
namespace {

// Issue 16: simulated times in JSON carry no binary float noise
// (0.19740000000000002 -> 0.1974): they are whole physics steps.
TEST(ResultJson, TimesHaveNoFloatNoise) {
  RunResult r;
  MoveRecord m;
  m.start_s = 0.1 + 0.2;                        // 0.30000000000000004
  m.travel_s = 1974 * 1e-4;                     // 0.19740000000000002
  m.settling_s = 0.1 * 3;                       // 0.30000000000000004
  m.positioning_s = m.travel_s + *m.settling_s; // 0.49740000000000006
  m.outcome = MoveOutcome::Done;
  r.moves = {m};
  r.sim_time_s = 181 * 0.002;                   // 0.36200000000000004
  const std::string text = to_json(r).dump();
  EXPECT_NE(text.find("\"start_s\":0.3,"), std::string::npos) << text;
  EXPECT_NE(text.find("\"travel_s\":0.1974"), std::string::npos) << text;
  EXPECT_NE(text.find("\"positioning_s\":0.4974,"), std::string::npos) << text;
  EXPECT_NE(text.find("\"sim_time_s\":0.362,"), std::string::npos) << text;
  EXPECT_EQ(text.find("0000000"), std::string::npos) << text;
}

} // namespace
} // namespace sreh
