// The figures of a run from its trace and judge(): the limit checks with
// their margins (A-SIZE-5), one place for the single move and the cycle.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "device_logic/faults.hpp"
#include "sizing/run_parts.hpp"
#include "sizing/thermal_estimate.hpp"

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

TorqueScan scan_torque(const std::vector<TraceRow>& rows, std::size_t from, TraceFigures& f) {
  TorqueScan scan;
  for (std::size_t r = from; r < rows.size(); ++r) {
    const double tq = std::abs(rows[r].torque_Nm);
    f.peak_torque_Nm = std::max(f.peak_torque_Nm, tq);
    if (rows[r].torque_limit_Nm > 0) {
      const double headroom = 1.0 - tq / rows[r].torque_limit_Nm;
      if (headroom < f.min_torque_headroom) {
        f.min_torque_headroom = headroom;
        scan.worst_headroom_speed_dps = std::abs(rows[r].velocity_dps);
      }
    }
    scan.warnings |= rows[r].warning_code;
  }
  return scan;
}

void derive_figures(const ModuleModel& module, const std::vector<TraceRow>& rows, std::size_t from,
                    std::size_t cycle_from, double dt_s, double ambient_C, double thermal_margin_K, TraceFigures& f) {
  f.supply = supply_figures(module.drive.motor, rows, from, cycle_from, dt_s, f.supply.bus_max_V);
  const ThermalEstimate th = estimate_thermal(f.mean_loss_W, ambient_C, module.thermal);
  f.steady_temperature_C = th.steady_C;
  f.time_to_warning_s = th.time_to_warning_s;
  f.time_to_trip_s = th.time_to_trip_s;
  f.continuous_torque_Nm = continuous_torque_Nm(ambient_C, thermal_margin_K, module);
  f.utilisation.peak_torque_pct = 100.0 * (1.0 - f.min_torque_headroom);
  f.utilisation.rms_torque_pct = f.continuous_torque_Nm > 0 ? 100.0 * f.rms_torque_Nm / f.continuous_torque_Nm : 0;
  f.utilisation.thermal_margin_K = kTemperatureWarning_C - f.steady_temperature_C;
}

LimitFigures limit_figures(const TraceFigures& f, const TorqueScan& scan, double voltage_V, double ambient_C,
                           double thermal_margin_K) {
  return LimitFigures{.warnings = scan.warnings,
                      .peak_torque_Nm = f.peak_torque_Nm,
                      .torque_capability_Nm = f.torque_capability_Nm,
                      .min_torque_headroom = f.min_torque_headroom,
                      .worst_headroom_speed_dps = scan.worst_headroom_speed_dps,
                      .voltage_V = voltage_V,
                      .max_tracking_error_deg = f.max_tracking_error_deg,
                      .tracking_limit_deg = f.tracking_limit_deg,
                      .steady_temperature_C = f.steady_temperature_C,
                      .ambient_C = ambient_C,
                      .thermal_margin_K = thermal_margin_K,
                      .time_to_warning_s = f.time_to_warning_s,
                      .positioning_target = {},
                      .cycle_target = {}};
}

void judge_into(const LimitFigures& limits, Reasons reasons, TraceFigures& f) {
  const Judgement j = judge(limits, std::move(reasons));
  f.feasible = j.feasible;
  f.reason = j.reason;
  f.binding_limit = j.binding_limit;
}

} // namespace sreh::sizing
