// The refit check (issue 36, A-CAL-12): does the fit give its own answer
// back? A log the fitted model would have recorded (the logged process data
// output replayed through the fitted card, with the log's noise) is fitted
// again from the same start. Where the refit lands further from the fitted
// value than the interval's half-width, the fit's error on this plan is
// larger than its interval says (a biased broad minimum, a solve that stops
// short on a flat cost): the constant is not identified and its interval is
// the card's range. Where it lands inside, the interval is widened by the
// refit's distance on both sides.
#pragma once
#include <vector>

#include "calibration/fit.hpp"

namespace sreh {

// The cases with every logged position (and polled temperature) replaced by
// what `card` gives, plus Gaussian noise of `noise_counts` (one sigma),
// rounded to whole wire counts and seeded by `seed` (deterministic).
std::vector<FitCase> synthetic_cases(const std::vector<FitCase>& cases, const ModelCard& card, double noise_counts,
                                     unsigned seed);

// The verdict of a refit (`refit`, one constant each, in `result`'s order)
// on `result`: a constant whose refit lands outside its interval is not
// identified; otherwise its interval widens by the refit's distance, and an
// identified one must then stay within +-kIdentifiedHalfWidth of its value
// and its interval is at least that wide.
inline constexpr double kIdentifiedHalfWidth = 0.10; // issue 36's tolerance
void apply_refit(const FitResult& refit, const ModelCard& start, FitResult& result);

} // namespace sreh
