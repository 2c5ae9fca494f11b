// Pieces of uncertainty sizing shared by its files (uncertainty.cpp:
// sampling and bands; robust.cpp: the search over every sample).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "sizing/uncertainty.hpp"

namespace sreh::sizing::uncertainty_parts {

// What the bands and the verdict are made of, for one move or one cycle.
struct Outcome {
  bool completed = false;
  bool feasible = false;
  double positioning_s = 0, settling_s = 0, peak_torque_Nm = 0, temperature_C = 0;
  std::optional<double> cycle_s;
  std::string binding_limit, reason;
};

Outcome outcome_of(const Evaluation& e);
Outcome outcome_of(const CycleEvaluation& e);

// The samples' verdict: feasible / incomplete counts, failures grouped by limit.
SampleVerdict verdict_of(const Outcome& nominal, const std::vector<Outcome>& outcomes);

// Bands over the nominal and the completed samples, the verdict, the
// sampled and fixed constants of `card`.
UncertaintyResult bands(const ModelCard& card, int samples, uint64_t seed, const Outcome& nominal,
                        const std::vector<Outcome>& outcomes);

// `set` evaluated on each card's model (no traces), on `threads` threads.
std::vector<Outcome> run_samples(const SizingRequest& request, const std::vector<ModelCard>& cards,
                                 const ParameterSetValues& set, int threads);

} // namespace sreh::sizing::uncertainty_parts
