// validate(), and size(): evaluate the given set, or search the fastest
// feasible one (A-SIZE-10): all three limits scaled together from the
// voltage's top speed and 100 %/100 % down until feasible, bisected, then
// acceleration/jerk and speed each raised again where that is faster.
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "device_logic/units.hpp"
#include "sizing/sizing.hpp"
#include "sizing/twin_factory.hpp"

namespace sreh::sizing {
namespace {

void check_range(const char* option, double value, double lo, double hi, const char* unit, const char* why) {
  if (!std::isfinite(value) || value < lo || value > hi) {
    throw SizingInputError(fmt::format("{} {} is outside {} .. {}{} ({})", option, value, lo, hi, unit, why));
  }
}

constexpr int kBisectSteps = 5;      // stage 1: the common scale to (hi - lo) / 32
constexpr int kRaiseSteps = 3;       // stages 2 and 3
constexpr double kMinScale = 1.0 / 64.0;

} // namespace

double validate(const SizingRequest& rq) {
  if (!std::isfinite(rq.angle_deg) || std::abs(rq.angle_deg) > kMaxAngle_deg) {
    throw SizingInputError(fmt::format("--angle-deg {} is outside +-{} deg (A-SIZE-1)", rq.angle_deg, kMaxAngle_deg));
  }
  if (deg_to_wire_counts(rq.angle_deg) == 0) {
    throw SizingInputError(fmt::format("--angle-deg {} is no move: below one position count (360/65536 deg, manual 2.5)",
                                       rq.angle_deg));
  }
  check_range("--voltage-V", rq.voltage_V, kMinVoltage_V, kMaxVoltage_V, " V",
              "the motor voltage window index 85 can be configured to, manual 6.2");
  check_range("--dwell-s", rq.dwell_s, 0.0, kMaxDwell_s, " s", "A-SIZE-1");
  check_range("--tolerance-deg", rq.tolerance_deg, 0.0, 65535.0 * 360.0 / 524288.0, " deg",
              "index 64+n.5: uint16 of 2^-19 rev, manual 6.2");
  check_range("--wait-ms", rq.wait_ms, 0.0, 5000.0, " ms", "index 64+n.6, manual 6.2");
  if (rq.timeout_ms) check_range("--timeout-ms", *rq.timeout_ms, 0.0, 5000.0, " ms", "index 64+n.7, manual 6.2");
  check_range("--ambient-C", rq.ambient_C, 0.0, 50.0, " degC", "A-SIZE-1");
  check_range("--parameter-set", rq.parameter_set, 0, 7, "", "index 64..71, manual 6.2");
  check_range("--cycles", rq.cycles, 1, 20, "", "A-SIZE-3");
  if (rq.setting) {
    const char* why = "manual 6.2, index 64..71";
    check_range("--speed-dps", rq.setting->speed_dps, 0.1, kMaxSpeed_dps, " deg/s", why);
    check_range("--accel-pct", rq.setting->accel_pct, 0.1, 100.0, " %", why);
    check_range("--jerk-pct", rq.setting->jerk_pct, 0.1, 100.0, " %", why);
  }
  if (const auto* j = std::get_if<InertiaLoad>(&rq.load)) {
    if (!std::isfinite(j->inertia_gcm2) || j->inertia_gcm2 < 0 || j->inertia_gcm2 > kMaxLoad_gcm2) {
      throw SizingInputError(fmt::format(
          "--load-gcm2 {} is outside 0 .. 15000 g cm^2 (the module's load limit, manual 3.5.6, 6.2 index 64.4)",
          j->inertia_gcm2));
    }
  }
  TwinConfig cfg;
  cfg.load = rq.load;
  cfg.record_trace = false;
  const double load = make_twin(cfg)->load_inertia_gcm2(); // the twin refuses > 15000 g cm^2 itself
  if (load > kMaxLoad_gcm2 + 1e-6) {
    throw SizingInputError(fmt::format("load inertia {:.1f} g cm^2 is above the module's limit of 15000 g cm^2 "
                                       "(manual 3.5.6, 6.2 index 64.4)", load));
  }
  return std::max(0.0, load); // no load reads -1e-12
}

SizingResult size(const SizingRequest& rq) {
  const double load_gcm2 = validate(rq);
  SizingResult result;
  if (rq.setting) {
    result.evaluation = evaluate(rq, make_parameter_set(rq, *rq.setting, load_gcm2), rq.keep_trace);
    result.simulations = 1;
    return result;
  }
  result.recommended = true;
  const double v_top = voltage_speed_limit_dps(rq.voltage_V);
  auto run = [&](double speed_scale, double accel_scale) {
    const MotionSetting s{v_top * speed_scale, 100.0 * accel_scale, 100.0 * accel_scale};
    Evaluation ev = evaluate(rq, make_parameter_set(rq, s, load_gcm2), false);
    ++result.simulations;
    result.tried.push_back(ev);
    return ev;
  };

  // Stage 1: one scale for speed, acceleration and jerk.
  std::optional<Evaluation> best;
  double lo = 0, hi = 1; // lo feasible (once found), hi infeasible
  double scale = 1;
  for (; scale >= kMinScale; scale /= 2) {
    Evaluation ev = run(scale, scale);
    if (ev.feasible) {
      best = std::move(ev);
      lo = scale;
      break;
    }
    hi = scale;
  }
  if (!best) {
    result.evaluation = result.tried.back();
    result.evaluation.reason = "no feasible set down to " + fmt::format("{:.1f}", 100 * kMinScale) +
                               " % of speed and acceleration: " + result.evaluation.reason;
    return result;
  }
  if (lo < 1) {
    for (int i = 0; i < kBisectSteps; ++i) {
      const double mid = 0.5 * (lo + hi);
      Evaluation ev = run(mid, mid);
      if (ev.feasible) { // a larger scale than the best so far
        lo = mid;
        best = std::move(ev);
      } else {
        hi = mid;
      }
    }
    // Stages 2 and 3: raise acceleration/jerk, then speed, where that is not
    // slower (a speed the move never reaches costs nothing: taken at once).
    double accel_scale = lo, speed_scale = lo;
    for (int which = 0; which < 2; ++which) {
      double a = lo, b = 1.0; // a feasible, b to try
      for (int i = 0; i < kRaiseSteps; ++i) {
        const double mid = i == 0 ? b : 0.5 * (a + b);
        const double sp = which == 0 ? speed_scale : mid;
        const double ac = which == 0 ? mid : accel_scale;
        Evaluation ev = run(sp, ac);
        if (ev.feasible && ev.positioning_s <= best->positioning_s) {
          best = std::move(ev);
          a = mid;
          if (i == 0) break; // the full value works
        } else {
          b = mid;
        }
      }
      if (which == 0) accel_scale = a;
      else speed_scale = a;
    }
  }
  if (rq.keep_trace) {
    best = evaluate(rq, best->set, true); // deterministic: the same run again, with its trace
    ++result.simulations;
  }
  result.evaluation = std::move(*best);
  return result;
}

} // namespace sreh::sizing
