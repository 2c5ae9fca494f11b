// Temperature under continuous cycling (issue 8), from the twin's own lumped
// thermal model (twin/thermal.hpp, A-TWIN-THERMAL-*): the cycle's mean loss
// held constant (A-SIZE-6). The steady state is Thermal::steady_winding_C;
// the time to the 70 degC warning (manual 7.3 115.1) integrates the same
// model from ambient.
#pragma once
#include <optional>

namespace sreh::sizing {

struct ThermalEstimate {
  double steady_C = 0;
  std::optional<double> time_to_warning_s; // none if the warning is never reached
};

ThermalEstimate estimate_thermal(double mean_loss_W, double ambient_C);

} // namespace sreh::sizing
