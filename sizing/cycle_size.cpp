// size_cycle: plan the sets, recommend the ones the file does not give,
// run the cycle (A-SIZE-20).
#include <algorithm>
#include <cmath>
#include <exception>
#include <thread>

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
  // The searches run side by side; each may also look one candidate ahead
  // (search.cpp Speculation): a search that ends first leaves its core to
  // the other's look ahead. The answer does not depend on it.
  s.search_threads = rq.threads;
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
  std::vector<MotionSetting> settings(plan.sets.size());
  std::vector<bool> searched;
  std::vector<std::size_t> to_search;
  for (std::size_t k = 0; k < plan.sets.size(); ++k) {
    const SetPlan& p = plan.sets[k];
    searched.push_back(!p.given);
    if (p.given) {
      settings[k] = *p.given;
      continue;
    }
    result.recommended = true;
    if (deg_to_wire_counts(p.longest_move_deg) != 0) to_search.push_back(k); // else only zero-length moves: nothing to size
  }
  // Each set's search is independent of the others: on several threads
  // when given them (issue 37), the results taken in set order as before.
  std::vector<SizingResult> found(plan.sets.size());
  const auto search = [&](std::size_t k) {
    const SetPlan& p = plan.sets[k];
    found[k] = search_fastest(single_request(rq, p, dwell_s / std::max(1, moves)), p.load_gcm2);
  };
  std::vector<std::thread> workers;
  std::vector<std::exception_ptr> errors(to_search.size());
  const std::size_t threads = std::min(to_search.size(), static_cast<std::size_t>(std::max(1, rq.threads)));
  for (std::size_t t = 1; t < threads; ++t) {
    workers.emplace_back([&, t] {
      for (std::size_t i = t; i < to_search.size(); i += threads) {
        try {
          search(to_search[i]);
        } catch (...) {
          errors[i] = std::current_exception();
        }
      }
    });
  }
  for (std::size_t i = 0; i < to_search.size(); i += std::max<std::size_t>(1, threads)) {
    try {
      search(to_search[i]);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  }
  for (std::thread& w : workers) w.join();
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }
  for (std::size_t k : to_search) {
    result.simulations += found[k].simulations;
    settings[k] = found[k].evaluation.set.setting;
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
