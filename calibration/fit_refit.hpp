// The bootstrap (issue 36, A-CAL-12): how far does the fit land from a
// known answer on this plan? Logs the fitted model would have recorded
// (the logged process data output replayed through the fitted card, the
// log's quantisation, a fresh draw of the log's noise each) are fitted
// again as the log was, each from starts of its own. Their distances from the fitted value
// are draws of the estimator's error near this point (the replay is a
// rugged function of the constants: a quantised encoder, stick-slip, the
// log's counts; a solve ends where its start and the roughness take it),
// so each constant's interval is the fitted value plus and minus the t
// distribution's 95 % multiple of their rms distance, never narrower than
// the likelihood's interval.
#pragma once
#include <vector>

#include "calibration/fit.hpp"

namespace sreh {

// The cases with every logged position (and polled temperature) replaced by
// what `card` gives at a `step_divisor` times finer physics step than the
// cases' (a real module has no step: the refits must see the
// discretisation the fit's replay makes, and each step gives its own
// realisation of the count-level roughness), plus Gaussian noise of
// `noise_counts` (one sigma), rounded to whole wire counts and seeded by
// `seed` (deterministic).
// Each case's log is recorded with its load scaled by `load_scale` (the
// fitted load, A-CAL-14; empty: as stated); the cases keep their setups.
std::vector<FitCase> synthetic_cases(const std::vector<FitCase>& cases, const ModelCard& card,
                                     const std::vector<double>& load_scale, double noise_counts, unsigned seed,
                                     int step_divisor);
// Refit b's log is recorded at the fit's physics step divided by
// kFirstStepDivisor + b.
inline constexpr int kFirstStepDivisor = 3;

// The t distribution's two-sided 95 % quantile with `dof` degrees of freedom.
double t95(int dof);

// The bootstrap's verdict on `result` from its refits (`refits[b]`, one
// constant each, in `result`'s order): each constant's interval becomes the
// hull of its likelihood interval and value +- t95(B) * rms distance of the
// refits (within the range), and an identified constant whose interval is
// then wider than +-kWideHalfWidth is not identified. "Identified" promises
// issue 36's tolerance, within 10 % of the truth, at 95 %: an interval of
// +-25 % did not (the 2 s plan without a load: Coulomb friction +30.8 %
// with +-24 %, A-CAL-12).
inline constexpr double kWideHalfWidth = 0.10; // an interval wider than +-10 % of the value: not identified
void apply_bootstrap(const std::vector<FitResult>& refits, FitResult& result);

} // namespace sreh
