// Sizing with the model's uncertainty (issues 26, 35): the same move and
// parameter set evaluated on module models sampled over the model card's
// ranges (Latin hypercube, seeded), so a sizing answer comes with how much
// it depends on constants nobody has measured; a calibrated model file
// (narrow ranges, calibrate --out) narrows the band. A-SIZE-UNC-1..3.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sizing/cycle.hpp"
#include "sizing/sizing.hpp"
#include "twin/model_card.hpp"

namespace sreh::sizing {

// A figure over the nominal model and every completed sample: lowest,
// highest, and the 5th / 50th / 95th percentile (linear between ranks).
struct Band {
  double lo = 0;
  double hi = 0;
  double p5 = 0, median = 0, p95 = 0;
};
Band band_of(std::vector<double> values); // values not empty

// The samples that failed on one limit (their binding limit, A-SIZE-5).
struct FailureGroup {
  std::string limit;        // binding_limit tag (JSON)
  std::string words;        // what failed, in words ("peak torque above 90 % of the capability at speed")
  std::vector<int> samples; // 1-based sample numbers
  int incomplete = 0;       // of those, samples whose moves did not complete
  std::string example;      // the first such sample's reason
};

// What one parameter set did over the samples (A-SIZE-UNC-2).
struct SampleVerdict {
  int samples = 0;
  int feasible = 0;          // feasible samples (completed and within every limit)
  int incomplete = 0;        // samples with a move that did not complete: infeasible, never left out
  bool nominal_feasible = false;
  std::vector<FailureGroup> failures; // most samples first
  bool all() const { return nominal_feasible && feasible == samples; }
  // "feasible in 27 of 32 samples: at risk (peak torque above 90 % ... in 5)"
  std::string sentence() const;
};

// With --uncertainty and a searched set (A-SIZE-UNC-3): the fastest (or,
// with a target, the gentlest) set feasible in every sample, against the
// nominal model's optimum.
struct RobustAnswer {
  bool searched = false;       // the nominal optimum failed in a sample: a robust search ran
  bool found = false;          // a set feasible on the nominal and in every sample
  std::string objective;       // the search's: "fastest", "gentlest"
  MotionSetting nominal_setting;
  double nominal_positioning_s = 0; // the nominal optimum's worst positioning time
  double nominal_cycle_s = 0;
  SampleVerdict nominal;       // the nominal optimum over the samples
  double slower_pct = 0;       // recommended positioning / nominal optimum's - 1, %
  std::string slowest_fails;   // not found because even the slowest grid point failed: why (else "")
  std::string sentence() const; // the recommendation in words
};

struct UncertaintyResult {
  int samples = 0;
  uint64_t seed = 0;
  std::vector<std::string> sampled; // the constants with a range wider than one value
  std::vector<std::string> fixed;   // the card's constants held at their value (a range of one value)
  Band positioning_s, settling_s, peak_torque_Nm, max_temperature_C;
  std::optional<Band> cycle_s;      // cycles only: the whole cycle's time
  bool feasible_worst_case = false; // the nominal and every sample feasible, every sample completed
  int infeasible_samples = 0;       // incomplete ones included
  int incomplete_samples = 0;       // a move did not reach Done: left out of the bands, counted infeasible
  int banded = 0;                   // evaluations in the bands (the nominal and completed samples); 0: no bands (null)
  SampleVerdict verdict;            // the answer's set over the samples
  RobustAnswer robust;              // size --uncertainty with a searched set
  // The one sentence text, JSON ("verdict") and report print.
  std::string sentence() const;
};

// `samples` models, each constant with a range wider than one value drawn
// by a Latin hypercube (one draw per stratum, strata shuffled per constant)
// from `seed`, the loop tuning included (A-SIZE-UNC-1). The bands cover the
// nominal evaluation too. Runs the samples on `threads` threads; the result
// does not depend on them.
UncertaintyResult size_uncertainty(const SizingRequest& request, const ModelCard& card, const Evaluation& nominal,
                                   int samples, uint64_t seed, int threads);

// size --uncertainty of one move (A-SIZE-UNC-3): size(), the answer on
// every sample, and for a searched set that fails in one, the search again
// judged on the nominal and every sample. `result` is the answer (with its
// trace when the request keeps one), `uncertainty` its bands and verdict.
struct UncertainSizing {
  SizingResult result;
  UncertaintyResult uncertainty;
};
UncertainSizing size_with_uncertainty(const SizingRequest& request, const ModelCard& card, int samples, uint64_t seed,
                                      int threads);

// The same for a cycle (`size --cycle --uncertainty`): the cycle run with
// the nominal answer's sets on every sampled model; positioning and
// settling are the worst move's, and the cycle time gets a band too.
UncertaintyResult cycle_uncertainty(const CycleRequest& request, const CyclePlan& plan,
                                    const std::vector<MotionSetting>& settings, const ModelCard& card,
                                    const CycleEvaluation& nominal, int samples, uint64_t seed, int threads);

// A cycle's times as the bands read them: its worst move's.
struct WorstMove {
  double positioning_s = 0;
  double settling_s = 0;
};
WorstMove worst_move(const CycleEvaluation& evaluation);

// `size --json` keys: positioning_s_range, settling_s_range,
// peak_torque_Nm_range, max_temperature_C_range ([lo, hi]), cycle_s_range
// (cycles), feasible_worst_case, verdict (the sentence), and `uncertainty`
// {samples, seed, sampling, sampled, fixed, feasible_samples,
// infeasible_samples, incomplete_samples, bands {figure: {lo, p5, median,
// p95, hi}}, failures [...], robust {...}}.
void add_uncertainty_json(nlohmann::json& json, const UncertaintyResult& u);

// The text block of `size --uncertainty` (text output): the verdict, the
// band of each figure, what failed, and the sampled / fixed constants.
std::string uncertainty_text(const UncertaintyResult& u);

// A binding limit (A-SIZE-5) in words.
std::string limit_words(const std::string& limit);

// The sampled cards themselves (tests, docs).
std::vector<ModelCard> latin_hypercube_cards(const ModelCard& card, int samples, uint64_t seed);

} // namespace sreh::sizing
