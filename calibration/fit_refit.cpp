#include "calibration/fit_refit.hpp"

#include <cmath>
#include <random>

#include "device_logic/process_data.hpp"

namespace sreh {

std::vector<FitCase> synthetic_cases(const std::vector<FitCase>& cases, const ModelCard& card, double noise_counts,
                                     unsigned seed) {
  std::vector<FitCase> out = cases;
  const ModuleModel module = card.module_model();
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_counts);
  for (FitCase& c : out) {
    const ReplayTrack track = replay(c.setup, module, c.log);
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

} // namespace sreh
