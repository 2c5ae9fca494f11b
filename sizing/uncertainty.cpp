#include "sizing/uncertainty.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "io/parallel.hpp"
#include "sizing/uncertainty_parts.hpp"

namespace sreh::sizing {
namespace {

// Uniform in [0, 1) from the top 53 bits: the same numbers on every
// standard library (std::uniform_real_distribution is not specified bit for bit).
double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// Every constant whose range on the card (or the --model file) is wider
// than one value: what the card says production modules spread over,
// the loop tuning included (A-SIZE-UNC-1). No list of names here: a
// constant the card fixes has a range of one value. Where a calibration
// wrote an identified constant's 95 % interval (A-CAL-5), that is sampled
// instead of the range.
bool sampled(const ModelConstant& k) { return k.sampling_hi() > k.sampling_lo(); }

} // namespace

Band band_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const auto at = [&](double p) {
    const double pos = p * static_cast<double>(v.size() - 1);
    const auto i = static_cast<std::size_t>(std::floor(pos));
    const std::size_t j = std::min(i + 1, v.size() - 1);
    return v[i] + (pos - static_cast<double>(i)) * (v[j] - v[i]);
  };
  return {v.front(), v.back(), at(0.05), at(0.5), at(0.95)};
}

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
      double v = k.sampling_lo() + u * (k.sampling_hi() - k.sampling_lo());
      if (model_constant_is_whole(k.name)) v = std::round(v);
      cards[i].constants[c].value = std::clamp(v, k.sampling_lo(), k.sampling_hi());
    }
  }
  return cards;
}

namespace uncertainty_parts {

Outcome outcome_of(const Evaluation& e) {
  return {e.completed, e.feasible, e.positioning_s, e.settling_s, e.peak_torque_Nm, e.steady_temperature_C, {},
          e.binding_limit, e.reason};
}

Outcome outcome_of(const CycleEvaluation& e) {
  const WorstMove w = worst_move(e);
  return {e.completed, e.feasible, w.positioning_s, w.settling_s, e.peak_torque_Nm, e.steady_temperature_C, e.cycle_s,
          e.binding_limit, e.reason};
}

SampleVerdict verdict_of(const Outcome& nominal, const std::vector<Outcome>& outcomes) {
  SampleVerdict v;
  v.samples = static_cast<int>(outcomes.size());
  v.nominal_feasible = nominal.completed && nominal.feasible;
  std::map<std::string, FailureGroup> groups;
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    const Outcome& e = outcomes[i];
    if (!e.completed) ++v.incomplete;
    if (e.completed && e.feasible) {
      ++v.feasible;
      continue;
    }
    // A run that failed without naming a limit still failed: never left out.
    const std::string limit = e.binding_limit.empty() ? "device_error" : e.binding_limit;
    FailureGroup& g = groups[limit];
    if (g.samples.empty()) {
      g.limit = limit;
      g.words = limit_words(limit);
      g.example = e.reason;
    }
    g.samples.push_back(static_cast<int>(i) + 1);
    if (!e.completed) ++g.incomplete;
  }
  for (auto& [limit, g] : groups) v.failures.push_back(std::move(g));
  std::stable_sort(v.failures.begin(), v.failures.end(),
                   [](const FailureGroup& a, const FailureGroup& b) { return a.samples.size() > b.samples.size(); });
  return v;
}

UncertaintyResult bands(const ModelCard& card, int samples, uint64_t seed, const Outcome& nominal,
                        const std::vector<Outcome>& outcomes) {
  UncertaintyResult u;
  u.samples = samples;
  u.seed = seed;
  for (const ModelConstant& k : card.constants) (sampled(k) ? u.sampled : u.fixed).push_back(k.name);
  // An unfinished move has no times to band: only completed evaluations
  // are in the bands; the verdict counts the others as infeasible.
  std::vector<double> pos, settle, torque, temp, cycle;
  auto add = [&](const Outcome& e) {
    if (!e.completed) return;
    pos.push_back(e.positioning_s);
    settle.push_back(e.settling_s);
    torque.push_back(e.peak_torque_Nm);
    temp.push_back(e.temperature_C);
    if (e.cycle_s) cycle.push_back(*e.cycle_s);
    ++u.banded;
  };
  add(nominal);
  for (const Outcome& e : outcomes) add(e);
  if (u.banded > 0) {
    u.positioning_s = band_of(pos);
    u.settling_s = band_of(settle);
    u.peak_torque_Nm = band_of(torque);
    u.max_temperature_C = band_of(temp);
    if (!cycle.empty()) u.cycle_s = band_of(cycle);
  }
  u.verdict = verdict_of(nominal, outcomes);
  u.feasible_worst_case = u.verdict.all();
  u.infeasible_samples = u.verdict.samples - u.verdict.feasible;
  u.incomplete_samples = u.verdict.incomplete;
  return u;
}

std::vector<Outcome> run_samples(const SizingRequest& request, const std::vector<ModelCard>& cards,
                                 const ParameterSetValues& set, int threads) {
  std::vector<Outcome> outcomes(cards.size());
  io::parallel_for(cards.size(), threads, [&](std::size_t i) {
    SizingRequest rq = request;
    rq.world.module = cards[i].module_model();
    rq.keep_trace = false;
    outcomes[i] = outcome_of(evaluate(rq, set, false));
  });
  return outcomes;
}

} // namespace uncertainty_parts

using namespace uncertainty_parts;

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
  return bands(card, samples, seed, outcome_of(nominal), run_samples(request, cards, nominal.set, threads));
}

UncertaintyResult cycle_uncertainty(const CycleRequest& request, const CyclePlan& plan,
                                    const std::vector<MotionSetting>& settings, const ModelCard& card,
                                    const CycleEvaluation& nominal, int samples, uint64_t seed, int threads) {
  const std::vector<ModelCard> cards = latin_hypercube_cards(card, samples, seed);
  std::vector<Outcome> outcomes(cards.size());
  io::parallel_for(cards.size(), threads, [&](std::size_t i) {
    CycleRequest rq = request;
    rq.world.module = cards[i].module_model();
    rq.keep_trace = false;
    outcomes[i] = outcome_of(evaluate_cycle(rq, plan, settings, false));
  });
  return bands(card, samples, seed, outcome_of(nominal), outcomes);
}

} // namespace sreh::sizing
