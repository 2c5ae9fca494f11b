#include "sizing/uncertainty.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "io/parallel.hpp"

namespace sreh::sizing {
namespace {

// Uniform in [0, 1) from the top 53 bits: the same numbers on every
// standard library (std::uniform_real_distribution is not specified bit for bit).
double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

void widen(Band& b, double v, bool first) {
  if (first) b = {v, v};
  b.lo = std::min(b.lo, v);
  b.hi = std::max(b.hi, v);
}

// The firmware's loop tuning: the card's ranges for these say what a
// calibration may try, not how production modules spread
// (docs/model-card.md), so uncertainty sizing keeps them (A-SIZE-UNC-1).
bool firmware_tuning(const std::string& name) {
  static const char* const kNames[] = {"control_period",  "loop_delay",     "current_loop_bandwidth",
                                       "velocity_bandwidth", "velocity_schedule_exponent", "position_ratio",
                                       "integral_ratio",  "velocity_filter", "speed_filter"};
  for (const char* n : kNames) {
    if (name == n) return true;
  }
  return false;
}

bool sampled(const ModelConstant& k) { return k.range_hi > k.range_lo && !firmware_tuning(k.name); }

} // namespace

std::vector<ModelCard> latin_hypercube_cards(const ModelCard& card, int samples, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<ModelCard> cards(static_cast<std::size_t>(samples), card);
  const auto n = static_cast<std::size_t>(samples);
  for (std::size_t c = 0; c < card.constants.size(); ++c) {
    const ModelConstant& k = card.constants[c];
    if (!sampled(k)) continue;
    std::vector<std::size_t> strata(n);
    for (std::size_t i = 0; i < n; ++i) strata[i] = i;
    for (std::size_t i = n; i > 1; --i) std::swap(strata[i - 1], strata[static_cast<std::size_t>(unit(rng) * static_cast<double>(i))]);
    for (std::size_t i = 0; i < n; ++i) {
      const double u = (static_cast<double>(strata[i]) + unit(rng)) / static_cast<double>(n);
      double v = k.range_lo + u * (k.range_hi - k.range_lo);
      if (model_constant_is_whole(k.name)) v = std::round(v);
      cards[i].constants[c].value = std::clamp(v, k.range_lo, k.range_hi);
    }
  }
  return cards;
}

namespace {

// What the bands are made of, for one move or one cycle.
struct Outcome {
  bool completed = false;
  bool feasible = false;
  double positioning_s = 0, settling_s = 0, peak_torque_Nm = 0, temperature_C = 0;
  std::optional<double> cycle_s;
};

Outcome outcome_of(const Evaluation& e) {
  return {e.completed, e.feasible, e.positioning_s, e.settling_s, e.peak_torque_Nm, e.steady_temperature_C, {}};
}

Outcome outcome_of(const CycleEvaluation& e) {
  const WorstMove w = worst_move(e);
  return {e.completed, e.feasible, w.positioning_s, w.settling_s, e.peak_torque_Nm, e.steady_temperature_C, e.cycle_s};
}

UncertaintyResult bands(const ModelCard& card, int samples, uint64_t seed, const Outcome& nominal,
                        const std::vector<Outcome>& outcomes) {
  UncertaintyResult u;
  u.samples = samples;
  u.seed = seed;
  for (const ModelConstant& k : card.constants) {
    if (sampled(k)) u.sampled.push_back(k.name);
  }
  u.feasible_worst_case = nominal.feasible && nominal.completed;
  // An unfinished move has no times to band: only completed evaluations count.
  auto add = [&](const Outcome& e) {
    if (!e.completed) return;
    const bool first = u.banded == 0;
    widen(u.positioning_s, e.positioning_s, first);
    widen(u.settling_s, e.settling_s, first);
    widen(u.peak_torque_Nm, e.peak_torque_Nm, first);
    widen(u.max_temperature_C, e.temperature_C, first);
    if (e.cycle_s) {
      if (!u.cycle_s) u.cycle_s = Band{};
      widen(*u.cycle_s, *e.cycle_s, first);
    }
    ++u.banded;
  };
  add(nominal);
  for (const Outcome& e : outcomes) {
    add(e);
    if (!e.feasible || !e.completed) {
      u.feasible_worst_case = false;
      ++u.infeasible_samples;
    }
    if (!e.completed) ++u.incomplete_samples;
  }
  return u;
}

} // namespace

WorstMove worst_move(const CycleEvaluation& e) {
  WorstMove w;
  for (const SegmentResult& s : e.segments) {
    if (s.kind != "move") continue;
    w.positioning_s = std::max(w.positioning_s, s.positioning_s);
    w.settling_s = std::max(w.settling_s, s.settling_s);
  }
  return w;
}

UncertaintyResult size_uncertainty(const SizingRequest& request, const ModelCard& card, const Evaluation& nominal,
                                   int samples, uint64_t seed, int threads) {
  const std::vector<ModelCard> cards = latin_hypercube_cards(card, samples, seed);
  std::vector<Outcome> outcomes(cards.size());
  io::parallel_for(cards.size(), threads, [&](std::size_t i) {
    SizingRequest rq = request;
    rq.world.module = cards[i].module_model();
    outcomes[i] = outcome_of(evaluate(rq, nominal.set, false));
  });
  return bands(card, samples, seed, outcome_of(nominal), outcomes);
}

UncertaintyResult cycle_uncertainty(const CycleRequest& request, const CyclePlan& plan,
                                    const std::vector<MotionSetting>& settings, const ModelCard& card,
                                    const CycleEvaluation& nominal, int samples, uint64_t seed, int threads) {
  const std::vector<ModelCard> cards = latin_hypercube_cards(card, samples, seed);
  std::vector<Outcome> outcomes(cards.size());
  io::parallel_for(cards.size(), threads, [&](std::size_t i) {
    CycleRequest rq = request;
    rq.world.module = cards[i].module_model();
    outcomes[i] = outcome_of(evaluate_cycle(rq, plan, settings, false));
  });
  return bands(card, samples, seed, outcome_of(nominal), outcomes);
}

void add_uncertainty_json(nlohmann::json& json, const UncertaintyResult& u) {
  auto band = [&](const Band& b) { return u.banded ? nlohmann::json::array({b.lo, b.hi}) : nlohmann::json(); };
  // Times on the nanosecond grid, as `size --json` writes them (output.cpp).
  auto ns = [](double v) { return std::round(v * 1e9) / 1e9; };
  auto time_band = [&](const Band& b) { return u.banded ? nlohmann::json::array({ns(b.lo), ns(b.hi)}) : nlohmann::json(); };
  json["positioning_s_range"] = time_band(u.positioning_s);
  json["settling_s_range"] = time_band(u.settling_s);
  json["peak_torque_Nm_range"] = band(u.peak_torque_Nm);
  json["max_temperature_C_range"] = band(u.max_temperature_C);
  if (u.cycle_s) json["cycle_s_range"] = time_band(*u.cycle_s);
  json["feasible_worst_case"] = u.feasible_worst_case;
  json["uncertainty"] = {{"samples", u.samples},
                         {"seed", u.seed},
                         {"sampling", "latin_hypercube"},
                         {"sampled", u.sampled},
                         {"infeasible_samples", u.infeasible_samples},
                         {"incomplete_samples", u.incomplete_samples}};
}

} // namespace sreh::sizing
