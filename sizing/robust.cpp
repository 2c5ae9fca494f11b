// size --uncertainty of one move (issue 35, A-SIZE-UNC-3): the answer must
// hold on every sampled model. The nominal search runs first; its optimum
// is run on every sample; when it fails in one, the same search runs again
// with a judge that runs each set on the nominal model and then on the
// samples, those that failed last first, and stops at the first failure.
// The search's pruning stays exact: a set at least as fast as one that
// failed on some model fails on that model too (A-SIZE-10), so it fails
// the robust judgement.
#include <algorithm>
#include <map>
#include <tuple>

#include <fmt/format.h>

#include "io/parallel.hpp"
#include "sizing/uncertainty.hpp"
#include "sizing/uncertainty_parts.hpp"

namespace sreh::sizing {
namespace {

using namespace uncertainty_parts;

// Samples run in fixed batches: the failure recorded (the first in the
// order within the first failing batch) is the same on any thread count.
// The sample that failed last runs alone first: it usually fails again.
constexpr std::size_t kBatch = 4;
std::size_t batch_at(std::size_t from) { return from == 0 ? 1 : kBatch; }

class RobustJudge {
 public:
  RobustJudge(const std::vector<ModelCard>& cards, int threads, const SampleVerdict& first)
      : threads_(threads) {
    for (const ModelCard& c : cards) models_.push_back(c.module_model());
    // Those that failed the nominal optimum first: they are the likeliest to fail again.
    for (const FailureGroup& g : first.failures) {
      for (int s : g.samples) order_.push_back(static_cast<std::size_t>(s - 1));
    }
    for (std::size_t i = 0; i < models_.size(); ++i) {
      if (std::find(order_.begin(), order_.end(), i) == order_.end()) order_.push_back(i);
    }
  }

  Evaluation operator()(const SizingRequest& rq, const ParameterSetValues& set) {
    ++runs_;
    Evaluation nominal = evaluate(rq, set, false);
    if (!nominal.feasible) return nominal;
    std::vector<std::optional<Evaluation>> done(models_.size());
    for (std::size_t from = 0, n = 0; from < order_.size(); from += n) {
      n = std::min(batch_at(from), order_.size() - from);
      io::parallel_for(n, threads_, [&](std::size_t b) {
        const std::size_t k = order_[from + b];
        SizingRequest s = rq;
        s.world.module = models_[k];
        done[k] = evaluate(s, set, false);
      });
      runs_ += static_cast<int>(n);
      for (std::size_t b = 0; b < n; ++b) {
        const std::size_t k = order_[from + b];
        if (done[k]->feasible) continue;
        Evaluation failed = std::move(*done[k]);
        failed.reason = fmt::format("in sampled model {}: {}", k + 1, failed.reason);
        order_.erase(order_.begin() + static_cast<std::ptrdiff_t>(from + b));
        order_.insert(order_.begin(), k);
        return failed;
      }
    }
    std::vector<Outcome>& out = passed_[key(set)];
    out.clear();
    for (const std::optional<Evaluation>& e : done) out.push_back(outcome_of(*e));
    return nominal;
  }

  // The samples' outcomes of a set that passed on all of them, if it did.
  const std::vector<Outcome>* passed(const ParameterSetValues& set) const {
    const auto it = passed_.find(key(set));
    return it == passed_.end() ? nullptr : &it->second;
  }
  int runs() const { return runs_; }

 private:
  using Key = std::tuple<double, double, double>;
  static Key key(const ParameterSetValues& s) { return {s.setting.speed_dps, s.setting.accel_pct, s.setting.jerk_pct}; }

  int threads_;
  std::vector<ModuleModel> models_;
  std::vector<std::size_t> order_;
  std::map<Key, std::vector<Outcome>> passed_;
  int runs_ = 0;
};

// The slowest grid point, without the targets, on the samples where the
// nominal optimum failed other than on torque, heat or a target (those a
// slower set relieves): if it fails in one, every grid point does
// (A-SIZE-10's monotonicity, per model) and no search is needed. That is
// where a sampled tuning cannot hold the load at any speed (a limit cycle,
// a settling timeout). Its reason, or "" (then the search decides); adds
// its twin runs to `runs_made`.
std::string slowest_failure(const SizingRequest& rq, const std::vector<ModelCard>& cards, const SampleVerdict& nominal,
                            int threads, int& runs_made) {
  std::vector<std::size_t> suspects;
  for (const FailureGroup& g : nominal.failures) {
    if (g.limit == "torque_at_speed" || g.limit == "temperature" || g.limit == "max_positioning" || g.limit == "max_cycle") continue;
    for (int k : g.samples) suspects.push_back(static_cast<std::size_t>(k - 1));
  }
  std::sort(suspects.begin(), suspects.end());
  if (suspects.empty()) return {};
  SizingRequest slow = rq;
  slow.max_positioning_ms.reset();
  slow.max_cycle_ms.reset();
  const ParameterSetValues set = make_parameter_set(slow, slowest_setting(slow), validate(slow));
  std::vector<Evaluation> runs(suspects.size());
  runs_made += static_cast<int>(suspects.size());
  io::parallel_for(suspects.size(), threads, [&](std::size_t i) {
    SizingRequest s = slow;
    s.world.module = cards[suspects[i]].module_model();
    runs[i] = evaluate(s, set, false);
  });
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (!runs[i].feasible) {
      return fmt::format("{} in sampled model {}: {}", fmt::format("{:.1f} deg/s, {:.0f} %, {:.0f} %", set.tidy.speed_dps,
                                                                   set.tidy.accel_pct, set.tidy.jerk_pct),
                         suspects[i] + 1, runs[i].reason);
    }
  }
  return {};
}

} // namespace

UncertainSizing size_with_uncertainty(const SizingRequest& request, const ModelCard& card, int samples, uint64_t seed,
                                      int threads) {
  SizingRequest rq = request;
  UncertainSizing out;
  out.result = size(rq); // with its trace when asked: kept when the nominal answer stays
  rq.keep_trace = false;
  const std::vector<ModelCard> cards = latin_hypercube_cards(card, samples, seed);
  out.uncertainty = bands(card, samples, seed, outcome_of(out.result.evaluation),
                          run_samples(rq, cards, out.result.evaluation.set, threads));
  out.result.simulations += samples;
  if (out.result.recommended && out.result.feasible && !out.uncertainty.feasible_worst_case) {
    RobustAnswer robust;
    robust.searched = true;
    robust.objective = out.result.objective;
    robust.nominal_setting = out.result.evaluation.set.tidy;
    robust.nominal_positioning_s = out.result.evaluation.positioning_s;
    robust.nominal_cycle_s = out.result.evaluation.cycle_s;
    robust.nominal = out.uncertainty.verdict;
    RobustJudge judge(cards, threads, robust.nominal);
    int slow_runs = 0;
    robust.slowest_fails = slowest_failure(rq, cards, robust.nominal, threads, slow_runs);
    SizingResult r;
    if (robust.slowest_fails.empty()) {
      r = size(rq, [&judge](const SizingRequest& q, const ParameterSetValues& s) { return judge(q, s); });
    }
    const int simulations = out.result.simulations + slow_runs + judge.runs(); // the search's runs all go through the judge
    if (r.feasible) {
      const std::vector<Outcome>* passed = judge.passed(r.evaluation.set);
      std::vector<Outcome> outcomes = passed ? *passed : run_samples(rq, cards, r.evaluation.set, threads);
      out.uncertainty = bands(card, samples, seed, outcome_of(r.evaluation), outcomes);
      robust.found = true;
      robust.slower_pct = 100.0 * (r.evaluation.positioning_s / robust.nominal_positioning_s - 1.0);
      out.result = std::move(r);
    }
    out.result.simulations = simulations;
    out.uncertainty.robust = robust;
  }
  if (request.keep_trace && out.result.evaluation.trace.empty()) {
    out.result.evaluation = evaluate(request, out.result.evaluation.set, true); // deterministic: the same run, with its trace
    ++out.result.simulations;
  }
  return out;
}

} // namespace sreh::sizing
