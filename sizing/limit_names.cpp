#include "sizing/limit_names.hpp"

#include <utility>

namespace sreh::sizing {

std::string limit_in_words(const std::string& limit) {
  static const std::pair<const char*, const char*> kWords[] = {
      {"switch_on", "switching on"},
      {"settling", "settling in the tolerance window"},
      {"torque_at_speed", "peak torque at speed"},
      {"rms_torque", "RMS torque"},
      {"tracking", "tracking error"},
      {"temperature", "temperature margin"},
      {"voltage", "supply voltage"},
      {"max_positioning", "required positioning time"},
      {"max_cycle", "required cycle time"},
      {"module_limits", "the module's top speed, acceleration and jerk"}};
  for (const auto& [tag, words] : kWords) {
    if (limit == tag) return words;
  }
  return limit;
}

} // namespace sreh::sizing
