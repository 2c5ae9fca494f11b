// libFuzzer target: the load file loader of `sreh-twin size --load`. Any
// bytes: a LoadSpec or a ScenarioError, never another exception or a crash.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scenarios/load_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)sreh::parse_load_text(text, "fuzz_load.yaml", SREH_SOURCE_DIR "/scenarios");
  } catch (const sreh::ScenarioError&) {
  }
  return 0;
}
