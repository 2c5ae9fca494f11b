// Issue 36's done-when, shared by the calibration tests: what a fit of a
// hidden truth must give (every reported 95 % interval holds the truth,
// every constant flagged identified is within a tolerance) and what the
// fitted card must predict (a held-out move: 135 deg with its own
// parameter set, in no plan).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "calibration/fit.hpp"
#include "calibration_rig.hpp"

namespace sreh::test {

// The bootstrap's refits of a constant (A-CAL-12), for the test's output.
inline std::string refits_text(const FittedConstant& f) {
  std::string s = "[";
  for (const double r : f.refits) s += (s.size() > 1 ? ", " : "") + std::to_string(r);
  return s + "]";
}

// Every constant flagged identified is within `tolerance` of the truth, and
// every reported 95 % interval (identified or not) contains it; at least
// `identified` of them are identified. A fitted load's truth is
// `carried_gcm2`, the load the module carries.
inline void expect_recovered(const FitResult& fit, const ModelCard& hidden, double tolerance, int identified,
                             double carried_gcm2 = 0) {
  int flagged = 0;
  for (const FittedConstant& f : fit.constants) {
    ASSERT_TRUE(f.load || hidden.find(f.name)) << f.name;
    const double truth = f.load ? carried_gcm2 : hidden.find(f.name)->value;
    std::printf("%-22s truth %-10g start %-10g fit %-10g (%+.1f %%) ci95 [%g, %g] refits %s%s\n", f.name.c_str(), truth,
                f.start, f.value, 100 * (f.value / truth - 1), f.ci95_lo, f.ci95_hi, refits_text(f).c_str(),
                f.identified ? "" : (" not identified: " + f.note).c_str());
    EXPECT_LE(f.ci95_lo, truth) << f.name;
    EXPECT_GE(f.ci95_hi, truth) << f.name;
    if (f.identified) {
      ++flagged;
      EXPECT_NEAR(f.value, truth, tolerance * truth) << f.name;
    }
  }
  EXPECT_GE(flagged, identified);
}

// The held-out move on the fitted card against the truth's: the maximum
// tracking error within `tolerance`, the time into the window within
// max(`tolerance`, 2 ms); with `load_gcm2` attached (and configured).
// With `fitted_load_gcm2` (a fitted load): the truth carries `load_gcm2`
// and the fit its own, both on a set configured for `configured_gcm2`.
inline void expect_predicts_held_out(const ModelCard& fitted, const ModelCard& hidden, double tolerance,
                                     double load_gcm2 = 5000, std::optional<double> fitted_load_gcm2 = std::nullopt,
                                     std::optional<double> configured_gcm2 = std::nullopt) {
  const MoveRecord truth = held_out_move(hidden, load_gcm2, configured_gcm2);
  const MoveRecord predicted = held_out_move(fitted, fitted_load_gcm2.value_or(load_gcm2), configured_gcm2);
  ASSERT_TRUE(truth.in_window_s && predicted.in_window_s);
  std::printf("held-out: tracking %.5f vs %.5f deg, in window %.4f vs %.4f s\n", predicted.max_tracking_error_deg,
              truth.max_tracking_error_deg, *predicted.in_window_s, *truth.in_window_s);
  EXPECT_NEAR(predicted.max_tracking_error_deg, truth.max_tracking_error_deg, tolerance * truth.max_tracking_error_deg);
  EXPECT_NEAR(*predicted.in_window_s, *truth.in_window_s, std::max(tolerance * *truth.in_window_s, 0.002));
}

} // namespace sreh::test
