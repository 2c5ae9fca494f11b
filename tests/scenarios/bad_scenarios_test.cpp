// One test per kind of broken scenario in tests/scenarios/bad/: each is a
// ScenarioError (exit code 2 at the command line) naming file:line:col and
// what is wrong (interfaces.md exit codes).
#include <gtest/gtest.h>

#include <string>

#include "scenarios/runner.hpp"
#include "scenarios/scenario_parser.hpp"

namespace sreh {
namespace {

const std::string kBad = std::string(SREH_SOURCE_DIR) + "/tests/scenarios/bad/";

struct Expected {
  int line;
  int column; // 0: not asserted
  std::string text;
};

void expect_error(const std::string& file, const Expected& want, bool run = false) {
  const std::string path = kBad + file;
  try {
    const Scenario s = parse_scenario_file(path);
    if (run) run_scenario(s);
    ADD_FAILURE() << file << ": no ScenarioError";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.where().file, path);
    EXPECT_EQ(e.where().line, want.line) << e.what();
    if (want.column > 0) {
      EXPECT_EQ(e.where().column, want.column) << e.what();
    }
    EXPECT_NE(e.message().find(want.text), std::string::npos) << e.what();
    const std::string prefix = path + ":" + std::to_string(want.line) + ":";
    EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << e.what(); // "FILE:LINE:COL: what"
  }
}

TEST(BadScenario, UnknownKey) { expect_error("unknown_key.yaml", {4, 23, "unknown key 'moove'"}); }
TEST(BadScenario, WrongType) { expect_error("wrong_type.yaml", {5, 13, "expected a number, got 'soon'"}); }
TEST(BadScenario, OutOfRangeParameterSet) {
  // manual 2.2: the parameter set travels as a uint8.
  expect_error("out_of_range.yaml", {7, 22, "parameter_set: 300 is out of range 0..255"});
}
TEST(BadScenario, NegativeWait) { expect_error("negative_wait.yaml", {4, 13, "wait_s: -0.5 is out of range"}); }
TEST(BadScenario, BothTargets) { expect_error("both_targets.yaml", {4, 0, "target_deg or target_raw, not both"}); }
TEST(BadScenario, MissingLoadFile) { expect_error("missing_load_file.yaml", {4, 9, "file 'no_such_load.xml' not found"}); }
TEST(BadScenario, BadYamlSyntax) { expect_error("bad_syntax.yaml", {5, 0, "YAML syntax"}); }
TEST(BadScenario, MissingSteps) { expect_error("missing_steps.yaml", {2, 1, "missing required key 'steps'"}); }
TEST(BadScenario, TwoLoads) { expect_error("two_loads.yaml", {4, 3, "exactly one of"}); }
TEST(BadScenario, UnknownState) { expect_error("unknown_state.yaml", {4, 0, "unknown 'Finished'"}); }
TEST(BadScenario, WaitUntilWithoutLimit) { expect_error("wait_until_no_timeout.yaml", {4, 0, "missing required key 'within_s'"}); }

TEST(BadScenario, InvalidMjcfLoad) {
  // Only MuJoCo can tell valid MJCF: the twin rejects it, the runner cites the load.
  expect_error("invalid_mjcf.yaml", {4, 3, "load:"}, /*run=*/true);
}

} // namespace
} // namespace sreh
