// Run limits and streaming (issue 12): bounds known from the file, refused
// before running; a streamed trace has the bytes of the in-memory one.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "scenarios/limits.hpp"
#include "scenarios/runner.hpp"
#include "scenarios/scenario_parser.hpp"
#include "twin/trace.hpp"

namespace sreh {
namespace {

Scenario parse_limited(const std::string& text, const Limits& limits = {}) {
  return parse_scenario_text(text, "t.yaml", "", limits);
}

TEST(RunBound, CountsRepeatsTimesTheirStepsInWholeCycles) {
  const Scenario s = parse_limited(R"(name: x
steps:
  - pd: {motor_on: 1}
  - repeat:
      times: 3
      steps:
        - wait_s: 0.0031
        - expect: {state: Ready}
        - wait_until: {state: Done, within_s: 0.01}
)");
  const RunBound b = run_bound(s);
  // pd 1 cycle; per pass: 0.0031 s -> 2 cycles, wait_until 5 cycles.
  EXPECT_NEAR(b.sim_s, 0.002 + 3 * (0.004 + 0.010), 1e-12);
  EXPECT_DOUBLE_EQ(b.steps, 2 + 3 * 3);
  EXPECT_DOUBLE_EQ(b.checks, 3 * 2);
}

TEST(RunBound, RefusesBeforeRunningAndNamesTheStepAndOption) {
  const std::string text = R"(name: x
steps:
  - wait_s: 10
  - repeat:
      times: 1000
      steps:
        - wait_s: 10
)";
  Limits limits;
  limits.max_sim_s = 100;
  try {
    check_run_bound(parse_limited(text), limits);
    FAIL() << "not refused";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.where().line, 4);
    EXPECT_NE(std::string(e.what()).find("--max-sim-s"), std::string::npos) << e.what();
  }
  limits.max_sim_s = 10010;
  EXPECT_NO_THROW(check_run_bound(parse_limited(text), limits));
  // run_scenario checks it too (the library path: fuzzers, Python).
  limits.max_sim_s = 100;
  RunOptions o;
  o.limits = limits;
  EXPECT_THROW(run_scenario(parse_limited(text), o), ScenarioError);
}

TEST(RunBound, RepeatProductsBeyondIntegersStayFinite) {
  std::string text = "name: x\nsteps:\n";
  std::string indent = "  ";
  for (int i = 0; i < 6; ++i) {
    text += indent + "- repeat:\n" + indent + "    times: 100000\n" + indent + "    steps:\n";
    indent += "      ";
  }
  text += indent + "- comment: deep\n";
  const RunBound b = run_bound(parse_limited(text));
  EXPECT_GT(b.steps, 1e29);
  EXPECT_THROW(check_run_bound(parse_limited(text), Limits{}), ScenarioError);
}

TEST(YamlLimits, AliasExpansionDepthAndSizeAreBounded) {
  Limits small;
  small.max_yaml_nodes = 50;
  const std::string aliases = "name: x\na: &a [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\nb: [*a, *a, *a, *a, *a]\nsteps:\n  - wait_s: 1\n";
  try {
    parse_limited(aliases, small);
    FAIL() << "not refused";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("--max-yaml-nodes"), std::string::npos) << e.what();
  }
  small.max_yaml_nodes = 1000;
  small.max_yaml_depth = 3;
  EXPECT_THROW(parse_limited("name: x\nsteps:\n  - wait_s: [[1]]\n", small), ScenarioError);
  small.max_file_bytes = 10;
  EXPECT_THROW(parse_limited("name: x\nsteps:\n  - wait_s: 1\n", small), ScenarioError);
}

TEST(YamlTags, CoreTagsMustMatchTheirValue) {
  EXPECT_NO_THROW(parse_limited("name: !!str x\nsteps:\n  - wait_s: !!float 0.5\n  - wait_s: !!int 1\n"));
  EXPECT_THROW(parse_limited("name: x\nsteps:\n  - wait_s: !!str 5\n"), ScenarioError);
  EXPECT_THROW(parse_limited("name: x\nsteps:\n  - wait_s: !!int 0.5\n"), ScenarioError);
  EXPECT_THROW(parse_limited("name: x\nsteps:\n  - pd: {motor_on: !!str true}\n"), ScenarioError);
  EXPECT_THROW(parse_limited("name: !local x\nsteps:\n  - wait_s: 1\n"), ScenarioError);
}

TEST(TraceStreaming, StreamedBytesEqualTheInMemoryTrace) {
  const std::string text = R"(name: x
load: {inertia_gcm2: 2000}
steps:
  - pd: {motor_on: 1}
  - wait_s: 0.05
  - pd: {target_deg: 45, parameter_set: 1, move: 1}
  - wait_s: 0.3
)";
  RunOptions memory;
  memory.record_trace = true;
  const RunResult a = run_scenario(parse_limited(text), memory);
  std::ostringstream held;
  write_trace_csv(held, a.trace);

  std::ostringstream streamed;
  write_trace_header(streamed);
  RunOptions stream;
  stream.trace_sink = [&](const TraceRow& row) { write_trace_row(streamed, row); };
  const RunResult b = run_scenario(parse_limited(text), stream);
  EXPECT_TRUE(b.trace.empty()); // nothing held in memory
  EXPECT_GT(a.trace.size(), 100u);
  EXPECT_EQ(streamed.str(), held.str());
}

} // namespace
} // namespace sreh
