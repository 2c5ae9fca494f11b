// `run --json` streamed (issue 12): checks, failures and moves go to
// temporaries as the run makes them, and the assembled object has exactly
// the bytes of the same run printed from memory.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "scenarios/result_json.hpp"
#include "scenarios/result_json_stream.hpp"
#include "scenarios/runner.hpp"
#include "scenarios/scenario_parser.hpp"

namespace sreh {
namespace {

Scenario parse_streamed(const std::string& text) { return parse_scenario_text(text, "t.yaml", "", Limits{}); }

std::string in_memory_json(const std::string& text, int indent = 2, const nlohmann::json& extra = nlohmann::json::object()) {
  const RunResult r = run_scenario(parse_streamed(text));
  nlohmann::json j = to_json(r);
  j.update(extra);
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string streamed_json(const std::string& text, RunResult* out = nullptr, int indent = 2,
                          const nlohmann::json& extra = nlohmann::json::object()) {
  ResultJsonStream stream(indent);
  RunOptions options;
  stream.attach(options);
  const RunResult r = run_scenario(parse_streamed(text), options);
  std::ostringstream json;
  stream.write(json, r, extra);
  if (out) *out = r;
  return json.str();
}

// Passing and failing checks (two of them in a repeat), a finished move and
// one still open at the end, run metrics, a name with control characters,
// a quote, a backslash and a non-ASCII letter (escaped the same way in both paths).
constexpr const char* kBusyRun = "name: \"busy \\x01 run \\t \xC3\xBC \\\" \\\\\"\n"
                                 R"(expect:
  moves: 2
  moves_completed: 1
  max_settling_s: 0.5
steps:
  - pd: {motor_on: 1}
  - wait_until: {state: Ready, within_s: 0.02}
  - pd: {target_deg: 45, parameter_set: 1, move: 1}
  - wait_until: {state: Done, within_s: 0.5}
  - repeat:
      times: 2
      steps:
        - expect: {position_deg: [10, 11]}
        - expect: {state: Done}
  - pd: {move: 0}
  - pd: {target_deg: 0, move: 1}
  - wait_s: 0.02
)";

TEST(ResultJsonStream, StreamedBytesEqualTheInMemoryJson) {
  RunResult streamed;
  const std::string bytes = streamed_json(kBusyRun, &streamed);
  EXPECT_EQ(bytes, in_memory_json(kBusyRun));
  // It is the interesting case: both arrays and failures non-empty, nothing held.
  const nlohmann::json j = nlohmann::json::parse(bytes);
  EXPECT_EQ(j["moves"].size(), 2u);
  EXPECT_FALSE(j["moves"][1]["completed"].get<bool>()); // still open at the end
  EXPECT_GE(j["checks"].size(), 8u);
  EXPECT_EQ(j["failures"].size(), 3u); // position twice and max_settling_s (the open move counts as infinite)
  EXPECT_TRUE(streamed.checks.empty());
  EXPECT_TRUE(streamed.failures.empty());
  EXPECT_TRUE(streamed.moves.empty());
  EXPECT_EQ(streamed.checks_recorded, j["checks"].size());
  EXPECT_EQ(streamed.moves_recorded, 2u);
}

TEST(ResultJsonStream, CompactLinesWithExtraMembersAsTheInMemoryJson) {
  // `run DIR --json`: one line per file, with its "file" member.
  const nlohmann::json extra = {{"file", "dir/busy.yaml"}};
  const std::string line = streamed_json(kBusyRun, nullptr, -1, extra);
  EXPECT_EQ(line, in_memory_json(kBusyRun, -1, extra));
  EXPECT_EQ(line.find('\n'), std::string::npos);
  const std::string idle = "name: idle\nsteps:\n  - wait_s: 0.01\n";
  EXPECT_EQ(streamed_json(idle, nullptr, -1, extra), in_memory_json(idle, -1, extra));
}

TEST(ResultJsonStream, EmptyArraysAsTheInMemoryJson) {
  const std::string text = "name: idle\nsteps:\n  - wait_s: 0.01\n";
  EXPECT_EQ(streamed_json(text), in_memory_json(text));
  EXPECT_NE(streamed_json(text).find("\"checks\": []"), std::string::npos);
}

TEST(ResultJsonStream, StopOnFailureAsTheInMemoryJson) {
  const std::string text = R"(name: stop
stop_on_failure: true
expect:
  moves: 0
steps:
  - pd: {motor_on: 1}
  - wait_until: {state: Ready, within_s: 0.02}
  - expect: {state: ErrorOn}
  - expect: {state: Ready}
)";
  EXPECT_EQ(streamed_json(text), in_memory_json(text));
}

TEST(ResultJsonStream, RunMetricsCountTheStreamedMoves) {
  // The metrics sum up finished and open records alike, whether kept or streamed.
  RunResult streamed;
  streamed_json(kBusyRun, &streamed);
  const RunResult held = run_scenario(parse_streamed(kBusyRun));
  ASSERT_EQ(held.checks.size(), streamed.checks_recorded);
  EXPECT_EQ(held.checks_held, streamed.checks_held);
  EXPECT_EQ(held.moves.size(), streamed.moves_recorded);
  EXPECT_EQ(held.passed, streamed.passed);
}

} // namespace
} // namespace sreh
