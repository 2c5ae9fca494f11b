// Figures written at a stated resolution (issue 29): a number in CSV or JSON
// carries as many digits as its unit's resolution, not the float's noise
// (0.034121, not 0.034121338939809016). The unit is the one the name
// carries (`positioning_s`, `peak_torque_Nm`, ...; docs/interfaces.md has
// the table). Names without a known unit keep 9 significant digits.
#pragma once
#include <string_view>

namespace sreh::io {

// Decimals written for a figure named `name` (a JSON key or CSV column);
// -1 when its unit is not known (then 9 significant digits). Trailing
// qualifiers (`_range`, `_lo`, `_hi`) are looked through:
// `settling_s_range` is a time.
int figure_decimals(std::string_view name);

// The double nearest to `value` written at `name`'s resolution, so that its
// shortest round-trip text has no more digits than that resolution. -0 and
// values that round to zero become 0; non-finite values pass unchanged.
double round_figure(std::string_view name, double value);

// Rounds every floating-point member of a JSON document (nlohmann::json or
// anything with its interface) by its key; array elements by their array's
// key. Integers, strings and booleans are left alone.
template <class Json>
void round_figures(Json& j, std::string_view key = {}) {
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) round_figures(it.value(), it.key());
  } else if (j.is_array()) {
    for (auto& element : j) round_figures(element, key);
  } else if (j.is_number_float()) {
    j = round_figure(key, j.template get<double>());
  }
}

} // namespace sreh::io
