#include "calibration/fit_refit.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include <fmt/format.h>

#include "device_logic/process_data.hpp"

namespace sreh {

std::vector<FitCase> synthetic_cases(const std::vector<FitCase>& cases, const ModelCard& card,
                                     const std::vector<double>& load_scale, double noise_counts, unsigned seed,
                                     int step_divisor) {
  std::vector<FitCase> out = cases;
  const ModuleModel module = card.module_model();
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_counts);
  for (std::size_t n = 0; n < out.size(); ++n) {
    FitCase& c = out[n];
    // Recorded at a finer physics step than the fit replays with: the
    // module is continuous, and the twin's step is a model error the fit
    // makes on its log and must make on these (A-CAL-12).
    ReplaySetup module_setup = c.setup;
    module_setup.config.physics_dt_s /= step_divisor;
    if (n < load_scale.size()) module_setup.load_scale *= load_scale[n];
    const ReplayTrack track = replay(module_setup, module, c.log);
    for (std::size_t k = 0; k < c.log.rows.size(); ++k) {
      MasterLogRow& row = c.log.rows[k];
      ProcessDataIn in = decode_in(track.pd_in[k]);
      if (noise_counts > 0) in.position_raw += static_cast<int32_t>(std::lround(noise(rng)));
      row.pd_in = encode(in);
      // The sensor as index 112 reads it, 0.5 degC steps (manual 6.4), on the
      // row after the read: the frame's temperature is the previous cycle's.
      if (row.temperature_C) row.temperature_C = 0.5 * std::round(2 * track.temperature_C[k]);
    }
  }
  return out;
}

double t95(int dof) {
  static constexpr double kTable[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228};
  if (dof >= 1 && dof <= 10) return kTable[dof - 1];
  // Beyond the table: the normal quantile with the first-order correction.
  const double z = 1.959964;
  return z + (z * z * z + z) / (4.0 * dof);
}

void apply_bootstrap(const std::vector<FitResult>& refits, FitResult& result) {
  if (refits.empty()) return;
  const double multiple = t95(static_cast<int>(refits.size()));
  for (std::size_t i = 0; i < result.constants.size(); ++i) {
    FittedConstant& f = result.constants[i];
    double squares = 0;
    for (const FitResult& refit : refits) {
      const double r = refit.constants[i].value;
      f.refits.push_back(r);
      squares += (r - f.value) * (r - f.value);
    }
    // The refits' distances from the value that recorded their logs are the
    // estimator's error there, its bias included (a distance is measured
    // from the generating value, not from the refits' mean): the interval
    // is symmetric about the fit, half-width the t multiple of their rms
    // (B degrees of freedom: B distances from a known centre).
    const double half = multiple * std::sqrt(squares / static_cast<double>(refits.size()));
    const double lo = std::min(f.ci95_lo, f.value - half);
    const double hi = std::max(f.ci95_hi, f.value + half);
    f.ci95_lo = f.bootstrap_lo = std::max(f.range_lo, lo);
    f.ci95_hi = f.bootstrap_hi = std::min(f.range_hi, hi);
    // Its width before the range clips it: an interval that fills the range
    // is not narrow because the range is.
    const double reported_half = 0.5 * (hi - lo);
    if (f.identified && reported_half > kWideHalfWidth * std::abs(f.value)) {
      f.identified = false;
      f.note = fmt::format("wide interval: the refits of logs the fitted model records land {:.1f} % away (rms), "
                           "+-{:.0f} % of the value",
                           100 * std::sqrt(squares / static_cast<double>(refits.size())) / std::abs(f.value),
                           100 * reported_half / std::abs(f.value));
    }
  }
}

} // namespace sreh
