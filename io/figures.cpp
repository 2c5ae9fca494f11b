#include "io/figures.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <system_error>

namespace sreh::io {
namespace {

struct Resolution {
  std::string_view unit; // the name's last '_' part
  int decimals;
};

// One row per unit (docs/interfaces.md, "Figures"): fine enough for every
// use (a tolerance of 0.0055 deg, a 0.1 ms control period), coarse enough
// that no float noise shows.
constexpr std::array kResolutions{
    Resolution{"s", 6},    // 1 us
    Resolution{"ms", 3},   // 1 us
    Resolution{"deg", 6},  // 1e-6 deg (a wire count is 0.0055 deg)
    Resolution{"dps", 3},  // deg/s
    Resolution{"dps2", 3}, // deg/s^2
    Resolution{"Nm", 6},   // 1 uN m
    Resolution{"pct", 4},
    Resolution{"C", 4},    // as the trace
    Resolution{"K", 4},
    Resolution{"V", 4},
    Resolution{"A", 6},
    Resolution{"W", 6},
    Resolution{"J", 6},
    Resolution{"ohm", 6},
    Resolution{"F", 6},
    Resolution{"Hz", 3},
    Resolution{"gcm2", 3},
    Resolution{"kgm2", 10}, // = 1e-3 g cm^2
};
constexpr int kPerMinuteDecimals = 3; // `cycles_per_min`: a rate, not a time in minutes

constexpr std::array<std::string_view, 3> kQualifiers{"_range", "_lo", "_hi"};

std::string_view strip_qualifier(std::string_view name) {
  for (std::string_view q : kQualifiers) {
    if (name.size() > q.size() && name.ends_with(q)) return name.substr(0, name.size() - q.size());
  }
  return name;
}

double parse(const char* first, const char* last, double fallback) {
  double v = fallback;
  const auto r = std::from_chars(first, last, v);
  return r.ec == std::errc() ? v : fallback;
}

} // namespace

int figure_decimals(std::string_view name) {
  name = strip_qualifier(name);
  if (name.ends_with("_per_min")) return kPerMinuteDecimals;
  const std::size_t cut = name.rfind('_');
  if (cut == std::string_view::npos) return -1;
  const std::string_view unit = name.substr(cut + 1);
  for (const Resolution& r : kResolutions) {
    if (r.unit == unit) return r.decimals;
  }
  return -1;
}

double round_figure(std::string_view name, double value) {
  if (!std::isfinite(value)) return value;
  // Through decimal text: the double nearest "0.034121" prints as that,
  // where round(v * 1e6) / 1e6 may not.
  char buf[400];
  const int decimals = figure_decimals(name);
  const auto r = decimals >= 0 ? std::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed, decimals)
                               : std::to_chars(buf, buf + sizeof buf, value, std::chars_format::general, 9);
  if (r.ec != std::errc()) return value;
  const double rounded = parse(buf, r.ptr, value);
  return rounded == 0.0 ? 0.0 : rounded;
}

} // namespace sreh::io
