// Does the model explain the log at all (issue 36)? The fit's rms residual
// against the log's own floor: what a perfect model would leave, the wire's
// quantisation (one count of 360/2^16 deg, manual 2.5, uniform: q/sqrt(12))
// and the logged position's noise (stated, or estimated from the log's
// second differences). Far above that floor the residual is the model's
// error, not the noise, and the intervals that assume a right model mean
// nothing: the plan segment where the residual is largest is named
// (A-CAL-10).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "calibration/fit.hpp"

namespace sreh {

// A stretch of log rows with one process-data command (the rows between two
// changes of pd_out): a move and its hold, as the plan's PLC program ran it.
struct LogSegment {
  std::size_t log = 0;            // index into the cases
  std::size_t first = 0, end = 0; // rows [first, end) of that log
  double t0_s = 0, t1_s = 0;
  double target_deg = 0;          // the commanded target (pd_out), degrees
  double rms_deg = 0;             // of the residuals in the segment
  double mean_deg = 0;            // their mean: systematic when |mean| is a large part of rms
};

// The log's segments with the residuals' rms and mean in each; `residuals`
// as position_residuals_deg gives them (every case's rows in order).
std::vector<LogSegment> log_segments(const std::vector<FitCase>& cases, const std::vector<double>& residuals);

// The noise of the logged position, wire counts (one sigma), estimated
// from second differences of the logged counts on the rows where the
// module stands (status Ready, not Busy: manual 2.3) and the second
// difference is at most kQuietSecondDifference_counts: white noise e gives
// e[k-1] - 2 e[k] + e[k+1] a variance of 6 sigma^2, and at rest the
// quantisation error is constant. About 0.1 count for a noise-free log.
inline constexpr double kQuietSecondDifference_counts = 6;
double estimated_noise_counts(const std::vector<FitCase>& cases);

// One wire count, degrees.
inline constexpr double kWireCount_deg = 360.0 / 65536.0;
// The rms a right model leaves on a log with `noise_counts` of noise.
double residual_floor_deg(double noise_counts);
// A residual this many times the floor is the model's, not the noise's.
inline constexpr double kInadequateRatio = 3.0;

} // namespace sreh
