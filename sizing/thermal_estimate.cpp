#include "sizing/thermal_estimate.hpp"

#include "sizing/sizing.hpp"
#include "twin/thermal.hpp"

namespace sreh::sizing {

ThermalEstimate estimate_thermal(double mean_loss_W, double ambient_C) {
  Thermal thermal(ThermalSpec{ambient_C, 1.0});
  ThermalEstimate e;
  e.steady_C = thermal.steady_winding_C(mean_loss_W);
  if (e.steady_C < kTemperatureWarning_C) return e;
  // Backward Euler (stable for any step): 0.5 s steps against time constants
  // of 125 s and 20 min; the steady state lies above the warning, so the
  // loop ends (bounded at 10 days anyway).
  constexpr double kStep_s = 0.5;
  constexpr int kMaxSteps = 10 * 24 * 3600 * 2;
  for (int i = 1; i <= kMaxSteps; ++i) {
    thermal.step(kStep_s, mean_loss_W);
    if (thermal.sensor_C() >= kTemperatureWarning_C) {
      e.time_to_warning_s = i * kStep_s;
      break;
    }
  }
  return e;
}

} // namespace sreh::sizing
