#include "calibration/fit_adequacy.hpp"

#include <algorithm>
#include <cmath>

#include "calibration/master_log.hpp"

namespace sreh {

std::vector<LogSegment> log_segments(const std::vector<FitCase>& cases, const std::vector<double>& residuals) {
  std::vector<LogSegment> segments;
  std::size_t offset = 0;
  for (std::size_t c = 0; c < cases.size(); ++c) {
    const std::vector<MasterLogRow>& rows = cases[c].log.rows;
    std::size_t first = 0;
    for (std::size_t k = 1; k <= rows.size(); ++k) {
      if (k < rows.size() && rows[k].pd_out == rows[first].pd_out) continue;
      LogSegment s;
      s.log = c;
      s.first = first;
      s.end = k;
      s.t0_s = rows[first].t_s;
      s.t1_s = rows[k - 1].t_s;
      s.target_deg = decode_out(rows[first].pd_out).target_raw * kWireCount_deg;
      double sum = 0, sum2 = 0;
      for (std::size_t j = first; j < k; ++j) {
        sum += residuals[offset + j];
        sum2 += residuals[offset + j] * residuals[offset + j];
      }
      const double n = static_cast<double>(k - first);
      s.mean_deg = sum / n;
      s.rms_deg = std::sqrt(sum2 / n);
      segments.push_back(s);
      first = k;
    }
    offset += rows.size();
  }
  return segments;
}

double estimated_noise_counts(const std::vector<FitCase>& cases) {
  double sum = 0;
  std::size_t quiet = 0;
  for (const FitCase& c : cases) {
    const std::vector<MasterLogRow>& rows = c.log.rows;
    for (std::size_t k = 1; k + 1 < rows.size(); ++k) {
      const ProcessDataIn here = decode_in(rows[k].pd_in);
      if (!here.ready || here.busy) continue; // standing, no move running (manual 2.3): what remains is noise
      const double a = static_cast<double>(decode_in(rows[k - 1].pd_in).position_raw);
      const double b = static_cast<double>(decode_in(rows[k].pd_in).position_raw);
      const double d = static_cast<double>(decode_in(rows[k + 1].pd_in).position_raw);
      const double second = a - 2 * b + d;
      if (std::abs(second) > kQuietSecondDifference_counts) continue; // the settling's last swing, not noise
      sum += second * second;
      ++quiet;
    }
  }
  if (quiet == 0) return 0;
  // At rest the quantisation error is constant: the second differences hold the noise alone.
  return std::sqrt(sum / static_cast<double>(quiet) / 6.0);
}

double residual_floor_deg(double noise_counts) {
  return kWireCount_deg * std::sqrt(1.0 / 12.0 + noise_counts * noise_counts);
}

} // namespace sreh
