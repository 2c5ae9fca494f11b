#include "twin/thermal.hpp"

#include <cmath>
#include <stdexcept>

namespace sreh {

Thermal::Thermal(const ThermalSpec& spec, const ThermalConstants& constants)
    : spec_(spec), constants_(constants), winding_C_(spec.ambient_C), housing_C_(spec.ambient_C) {
  if (!(spec.time_scale > 0) || !std::isfinite(spec.ambient_C)) {
    throw std::invalid_argument("thermal: time_scale must be > 0 and ambient_C finite");
  }
}

void Thermal::set_ambient_C(double ambient_C) {
  if (!std::isfinite(ambient_C)) throw std::invalid_argument("thermal: ambient_C must be finite");
  spec_.ambient_C = ambient_C;
}

double Thermal::speed_loss_W(double velocity_rad_s) const {
  return constants_.speed_loss_W_per_rad_s * std::abs(velocity_rad_s);
}

double Thermal::steady_winding_C(double loss_W) const {
  return spec_.ambient_C + loss_W * (constants_.winding_to_housing_K_per_W + constants_.housing_to_ambient_K_per_W);
}

void Thermal::step(double dt_s, double loss_W) {
  // Backward Euler on the 2x2 linear system: stable for any time_scale.
  //   Cw dTw = P - (Tw - Th) / Rwh
  //   Ch dTh = (Tw - Th) / Rwh - (Th - Ta) / Rha
  const double h = dt_s * spec_.time_scale;
  const double gw = 1.0 / constants_.winding_to_housing_K_per_W;
  const double ga = 1.0 / constants_.housing_to_ambient_K_per_W;
  const double cw = constants_.winding_capacity_J_per_K / h;
  const double ch = constants_.housing_capacity_J_per_K / h;
  // [cw + gw, -gw; -gw, ch + gw + ga] [Tw; Th] = [cw Tw + P; ch Th + ga Ta]
  const double a11 = cw + gw, a12 = -gw, a21 = -gw, a22 = ch + gw + ga;
  const double b1 = cw * winding_C_ + loss_W;
  const double b2 = ch * housing_C_ + ga * spec_.ambient_C;
  const double det = a11 * a22 - a12 * a21;
  winding_C_ = (b1 * a22 - a12 * b2) / det;
  housing_C_ = (a11 * b2 - a21 * b1) / det;
}

} // namespace sreh
