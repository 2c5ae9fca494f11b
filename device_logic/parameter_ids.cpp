#include "device_logic/parameter_ids.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sreh {

const ParameterEntry& parameter_row(ParamId id) {
  const ParameterEntry* row = find_parameter(id.index, id.subindex);
  if (row == nullptr) {
    throw std::logic_error("no parameter " + std::to_string(id.index) + "." + std::to_string(id.subindex) +
                           " in the table");
  }
  return *row;
}

double raw_to_display(ParamId id, int64_t raw) { return static_cast<double>(raw) * parameter_row(id).display_scale; }

int64_t display_to_raw(ParamId id, double display) {
  const ParameterEntry& row = parameter_row(id);
  const double raw = std::round(display / row.display_scale);
  if (!(raw > static_cast<double>(row.min))) return row.min; // NaN too
  if (raw >= static_cast<double>(row.max)) return row.max;
  return static_cast<int64_t>(raw);
}

double display_min(ParamId id) { return raw_to_display(id, parameter_row(id).min); }
double display_max(ParamId id) { return raw_to_display(id, parameter_row(id).max); }
double display_default(ParamId id) { return raw_to_display(id, parameter_row(id).default_value); }

} // namespace sreh
