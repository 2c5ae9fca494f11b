// libFuzzer target: the scenario loader (YAML safety layer + parser + run
// bound). Any bytes: a Scenario or a ScenarioError, never another exception,
// a crash, a hang or unbounded memory (aliases, depth: scenarios/limits.hpp).
#include <cstddef>
#include <cstdint>
#include <string>

#include "scenarios/limits.hpp"
#include "scenarios/scenario_parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    // Relative files (MJCF, NVM images) resolve against the shipped scenarios.
    const sreh::Scenario s = sreh::parse_scenario_text(text, "fuzz.yaml", SREH_SOURCE_DIR "/scenarios");
    sreh::check_run_bound(s, sreh::Limits{});
  } catch (const sreh::ScenarioError&) {
  }
  return 0;
}
