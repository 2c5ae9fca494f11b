// size_cycle: plan the sets, recommend the ones the file does not give,
// run the cycle (A-SIZE-20).
#include <algorithm>
#include <cmath>

#include "device_logic/units.hpp"
#include "sizing/cycle.hpp"

namespace sreh::sizing {
namespace {

// A-SIZE-20: the back-off when the recommended sets fail together in the
// cycle: speed, acceleration and jerk of every recommended set times this,
// at most kMaxBackoffs times.
constexpr double kBackoffFactor = 0.85;
constexpr int kMaxBackoffs = 8;

double round_tenth(double v) { return std::max(0.1, std::round(v * 10.0) / 10.0); }

// The single-move question for one set (A-SIZE-20): its longest move back
// and forth in the cycle's world (supply, ambient, mounting, model card)
// with the set's load, with the cycle's dwell time shared among its moves.
SizingRequest single_request(const CycleRequest& rq, const SetPlan& p, double dwell_per_move_s) {
  SizingRequest s;
  s.angle_deg = p.longest_move_deg;
  s.world = rq.world;
  s.world.load = p.load;
  s.dwell_s = std::min(dwell_per_move_s, kMaxDwell_s);
  s.settling = rq.settling;
  s.parameter_set = p.set;
  s.thermal_margin_K = rq.thermal_margin_K;
  s.handshake_cycles = rq.handshake_cycles;
  s.on_simulation = rq.on_simulation;
  return s;
}

} // namespace

CycleResult size_cycle(const CycleRequest& rq) {
  const CyclePlan plan = plan_sets(rq);
  CycleResult result;
  double dwell_s = 0;
  int moves = 0;
  for (const CycleSegment& s : rq.segments) {
    if (const auto* d = std::get_if<CycleDwell>(&s.what)) dwell_s += d->dwell_s;
    if (std::holds_alternative<CycleMove>(s.what)) ++moves;
  }
  std::vector<MotionSetting> settings;
  std::vector<bool> searched;
  for (const SetPlan& p : plan.sets) {
    searched.push_back(!p.given);
    if (p.given) {
      settings.push_back(*p.given);
      continue;
    }
    result.recommended = true;
    if (deg_to_wire_counts(p.longest_move_deg) == 0) { // only zero-length moves: nothing to size
      settings.push_back(MotionSetting{});
      continue;
    }
    const SizingRequest single = single_request(rq, p, dwell_s / std::max(1, moves));
    const SizingResult r = search_fastest(single, p.load_gcm2);
    result.simulations += r.simulations;
    settings.push_back(r.evaluation.set.setting);
  }
  result.evaluation = evaluate_cycle(rq, plan, settings, rq.keep_trace);
  ++result.simulations;
  const auto fixable = [](const std::string& limit) {
    return limit == "temperature" || limit == "torque_at_speed" || limit == "tracking" || limit == "settling";
  };
  while (result.recommended && !result.evaluation.feasible && fixable(result.evaluation.binding_limit) &&
         result.backoffs < kMaxBackoffs) {
    for (std::size_t k = 0; k < settings.size(); ++k) {
      if (!searched[k]) continue;
      settings[k] = MotionSetting{round_tenth(settings[k].speed_dps * kBackoffFactor),
                                  round_tenth(settings[k].accel_pct * kBackoffFactor),
                                  round_tenth(settings[k].jerk_pct * kBackoffFactor)};
    }
    ++result.backoffs;
    result.evaluation = evaluate_cycle(rq, plan, settings, rq.keep_trace);
    ++result.simulations;
  }
  result.settings = std::move(settings);
  return result;
}

} // namespace sreh::sizing
