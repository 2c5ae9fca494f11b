// Sizing with the model's uncertainty (issue 26): the same move and
// parameter set evaluated on module models sampled over the model card's
// ranges (Latin hypercube, seeded), so a sizing answer comes with how much
// it depends on constants nobody has measured; a calibrated model file
// (narrow ranges, calibrate --out) narrows the band. A-SIZE-UNC-1.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "sizing/cycle.hpp"
#include "sizing/sizing.hpp"
#include "twin/model_card.hpp"

namespace sreh::sizing {

struct Band {
  double lo = 0;
  double hi = 0;
};

struct UncertaintyResult {
  int samples = 0;
  uint64_t seed = 0;
  std::vector<std::string> sampled; // the constants with a range wider than one value
  Band positioning_s, settling_s, peak_torque_Nm, max_temperature_C;
  std::optional<Band> cycle_s;      // cycles only: the whole cycle's time
  bool feasible_worst_case = false; // every sample feasible
  int infeasible_samples = 0;
  int incomplete_samples = 0;        // a move did not reach Done: left out of the bands
  int banded = 0;                    // evaluations in the bands (the nominal and completed samples); 0: no bands (null)
};

// `samples` models, each physical constant with a range drawn by a Latin
// hypercube (one draw per stratum, strata shuffled per constant) from
// `seed`; the firmware's loop tuning is kept at its value. The bands cover the nominal evaluation too. Runs the
// samples on `threads` threads; the result does not depend on them.
UncertaintyResult size_uncertainty(const SizingRequest& request, const ModelCard& card, const Evaluation& nominal,
                                   int samples, uint64_t seed, int threads);

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
// peak_torque_Nm_range, max_temperature_C_range ([lo, hi]),
// cycle_s_range (cycles), feasible_worst_case, and `uncertainty` {samples, seed, sampling, sampled, infeasible_samples}.
void add_uncertainty_json(nlohmann::json& json, const UncertaintyResult& u);

// The sampled cards themselves (tests, docs).
std::vector<ModelCard> latin_hypercube_cards(const ModelCard& card, int samples, uint64_t seed);

} // namespace sreh::sizing
