// Module temperature (index 112; warning >= 70 degC 115.1, error >= 75 degC
// 114.3): a lumped two-node model, winding -> housing -> ambient, heated by
// copper losses and a small speed-dependent loss. Every constant is an
// assumption on the model card (docs/assumptions/twin.md A-TWIN-THERMAL-*).
#pragma once
#include "twin/module_model.hpp"
#include "twin/specs.hpp"

namespace sreh {

class Thermal {
 public:
  Thermal(const ThermalSpec& spec, const ThermalConstants& constants); // constants: model card

  // Advances dt_s (scaled by ThermalSpec::time_scale) with `loss_W` into the winding.
  void step(double dt_s, double loss_W);

  // Speed-dependent loss at this flange speed.
  double speed_loss_W(double velocity_rad_s) const;

  double winding_C() const { return winding_C_; }
  double housing_C() const { return housing_C_; }
  double sensor_C() const { return winding_C_; } // A-TWIN-THERMAL-4: the sensor reads the winding node
  double ambient_C() const { return spec_.ambient_C; }
  // A changed room temperature: the nodes then relax towards it (throws on non-finite).
  void set_ambient_C(double ambient_C);
  // Steady state for a constant loss: ambient + P (R_wh + R_ha) at the winding.
  double steady_winding_C(double loss_W) const;
  const ThermalConstants& constants() const { return constants_; }

 private:
  // Backward Euler's matrix for a step h: the same numbers as computed in
  // every step, computed once per step size (issue 37: a step's divisions).
  struct Matrix {
    double h = 0, ga = 0, cw = 0, ch = 0, a11 = 0, a12 = 0, a21 = 0, a22 = 0, det = 0;
  };
  const Matrix& matrix(double h);

  ThermalSpec spec_;
  ThermalConstants constants_;
  double winding_C_;
  double housing_C_;
  Matrix matrix_;
};

} // namespace sreh
