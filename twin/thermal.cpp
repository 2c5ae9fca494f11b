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

const Thermal::Matrix& Thermal::matrix(double h) {
  if (matrix_.h == h) return matrix_;
  Matrix& k = matrix_;
  k.h = h;
  const double gw = 1.0 / constants_.winding_to_housing_K_per_W;
  k.ga = 1.0 / constants_.housing_to_ambient_K_per_W;
  k.cw = constants_.winding_capacity_J_per_K / h;
  k.ch = constants_.housing_capacity_J_per_K / h;
  k.a11 = k.cw + gw;
  k.a12 = -gw;
  k.a21 = -gw;
  k.a22 = k.ch + gw + k.ga;
  k.det = k.a11 * k.a22 - k.a12 * k.a21;
  return k;
}

void Thermal::step(double dt_s, double loss_W) {
  // Backward Euler on the 2x2 linear system: stable for any time_scale.
  //   Cw dTw = P - (Tw - Th) / Rwh
  //   Ch dTh = (Tw - Th) / Rwh - (Th - Ta) / Rha
  // [cw + gw, -gw; -gw, ch + gw + ga] [Tw; Th] = [cw Tw + P; ch Th + ga Ta]
  const Matrix& k = matrix(dt_s * spec_.time_scale);
  const double b1 = k.cw * winding_C_ + loss_W;
  const double b2 = k.ch * housing_C_ + k.ga * spec_.ambient_C;
  winding_C_ = (b1 * k.a22 - k.a12 * b2) / k.det;
  housing_C_ = (k.a11 * b2 - k.a21 * b1) / k.det;
}

} // namespace sreh
