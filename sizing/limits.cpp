// judge(): the limit checks with their margins (A-SIZE-5), one place for
// the single move and the cycle.
#include <fmt/format.h>

#include "device_logic/faults.hpp"
#include "sizing/run_parts.hpp"

namespace sreh::sizing {

Judgement judge(const LimitFigures& f, Reasons reasons) {
  const double warning_limit_C = kTemperatureWarning_C - f.thermal_margin_K;
  if (reasons.list.empty()) {
    const uint8_t w = f.warnings;
    if (w & (1u << static_cast<int>(WarningBit::Positioning))) reasons.add("settling", warning_text(w));
    else if (w != 0) reasons.add(w & (1u << static_cast<int>(WarningBit::Temperature)) ? "temperature" : "voltage",
                                 warning_text(w));
    if (f.peak_torque_Nm > kTorqueMargin * f.torque_capability_Nm) {
      reasons.add("torque_at_speed", fmt::format("peak torque {:.3f} N m is above {:.0f} % of the motor's {:.3f} N m",
                                                 f.peak_torque_Nm, 100 * kTorqueMargin, f.torque_capability_Nm));
    } else if (f.min_torque_headroom < 1.0 - kTorqueMargin) {
      reasons.add("torque_at_speed", fmt::format(
          "torque within {:.0f} % of the motor's capability at {:.0f} deg/s and {:.1f} V (manual 3.5.3: "
          "the reachable speed falls with the voltage)",
          100 * (1.0 - kTorqueMargin), f.worst_headroom_speed_dps, f.voltage_V));
    }
    if (f.tracking_limit_deg > 0 && f.max_tracking_error_deg > kTrackingMargin * f.tracking_limit_deg) {
      reasons.add("tracking", fmt::format("tracking error {:.3f} deg is above {:.0f} % of the {:.1f} deg limit (index 87.1)",
                                          f.max_tracking_error_deg, 100 * kTrackingMargin, f.tracking_limit_deg));
    }
    if (f.steady_temperature_C >= warning_limit_C) {
      reasons.add("temperature",
                  fmt::format("continuous cycling heats the module to {:.1f} degC, less than the required {:.1f} K "
                              "below the 70 degC warning (115.1){}",
                              f.steady_temperature_C, f.thermal_margin_K,
                              f.time_to_warning_s ? fmt::format("; warning after {:.0f} s", *f.time_to_warning_s) : ""));
    }
    if (f.positioning_target && f.positioning_target->first > f.positioning_target->second) {
      reasons.add("max_positioning", fmt::format("positioning {:.1f} ms is above the required {:.1f} ms",
                                                 f.positioning_target->first * 1e3, f.positioning_target->second * 1e3));
    }
    if (f.cycle_target && f.cycle_target->first > f.cycle_target->second) {
      reasons.add("max_cycle", fmt::format("cycle {:.1f} ms is above the required {:.1f} ms",
                                           f.cycle_target->first * 1e3, f.cycle_target->second * 1e3));
    }
  }
  Judgement j;
  j.feasible = reasons.list.empty();
  for (const auto& r : reasons.list) j.reason += (j.reason.empty() ? "" : "; ") + r.second;
  if (!j.feasible) {
    j.binding_limit = reasons.list.front().first;
    return j;
  }
  // The limit closest to failing: the largest used fraction of what the margin allows.
  const double rise_allowed = warning_limit_C - f.ambient_C;
  auto ratio = [](const std::optional<std::pair<double, double>>& t) { return t ? t->first / t->second : 0.0; };
  const std::pair<double, const char*> used[] = {
      {(1.0 - f.min_torque_headroom) / kTorqueMargin, "torque_at_speed"},
      {f.tracking_limit_deg > 0 ? f.max_tracking_error_deg / (kTrackingMargin * f.tracking_limit_deg) : 0.0, "tracking"},
      {rise_allowed > 0 ? (f.steady_temperature_C - f.ambient_C) / rise_allowed : 1.0, "temperature"},
      {ratio(f.positioning_target), "max_positioning"},
      {ratio(f.cycle_target), "max_cycle"}};
  const auto* top = &used[0];
  for (const auto& u : used) if (u.first > top->first) top = &u;
  j.binding_limit = top->second;
  return j;
}

} // namespace sreh::sizing
