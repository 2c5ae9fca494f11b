// Temperature under continuous cycling (issue 8), from the twin's own lumped
// thermal model (twin/thermal.hpp, A-TWIN-THERMAL-*): the cycle's mean loss
// held constant (A-SIZE-6). The steady state is Thermal::steady_winding_C;
// the times to the 70 degC warning (manual 7.3 115.1) and to the 75 degC
// error (manual 7.2 114.3, the trip) integrate the same model from ambient.
#pragma once
#include "twin/module_model.hpp"
#include <optional>
#include <vector>

namespace sreh::sizing {

// Manual 7.2: overtemperature error 114.3 at >= 75 degC.
inline constexpr double kTemperatureTrip_C = 75.0;

struct ThermalEstimate {
  double steady_C = 0;
  std::optional<double> time_to_warning_s; // none if the warning is never reached
  std::optional<double> time_to_trip_s;    // none if 75 degC is never reached
};

ThermalEstimate estimate_thermal(double mean_loss_W, double ambient_C, const ThermalConstants& constants);

// The sensed temperature from ambient under the constant mean loss, sampled
// every `step_s` up to `duration_s` (for the report's plot): {t_s, C}.
struct TemperaturePoint {
  double t_s = 0;
  double C = 0;
};
std::vector<TemperaturePoint> temperature_curve(double mean_loss_W, double ambient_C, double duration_s,
                                                double step_s, const ThermalConstants& constants);

} // namespace sreh::sizing
