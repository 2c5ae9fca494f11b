#include "scenarios/scenario.hpp"
#include "scenarios/source_loc.hpp"

#include <cmath>

#include <fmt/format.h>

#include "io/text.hpp"

namespace sreh {

std::string SourceLoc::str() const {
  if (line <= 0) return file;
  return fmt::format("{}:{}:{}", file, line, column);
}

// Messages echo values from the file: control characters escaped, one line (issue 12).
ScenarioError::ScenarioError(const SourceLoc& loc, const std::string& message)
    : std::runtime_error(io::escape_control(loc.str() + ": " + message)), loc_(loc),
      message_(io::escape_control(message)) {}

std::string Range::str() const {
  if (exact) return fmt::format("{}", (min + max) / 2);
  if (std::isinf(min) && std::isinf(max)) return "any";
  if (std::isinf(min)) return fmt::format("<= {}", max);
  if (std::isinf(max)) return fmt::format(">= {}", min);
  return fmt::format("[{}, {}]", min, max);
}

bool Conditions::empty() const {
  return state.empty() && !position_deg && !position_raw && !error_code && !warning_code && !error && !warning &&
         led.empty() && iolink_led.empty() && !temperature_C && !supply_V && !velocity_dps && !tracking_error_deg;
}

} // namespace sreh
