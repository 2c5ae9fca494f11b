// Module temperature (index 112; warning >= 70 degC 115.1, error >= 75 degC
// 114.3): a lumped two-node model, winding -> housing -> ambient, heated by
// copper losses and a small speed-dependent loss. Every constant is an
// assumption (docs/assumptions/twin.md A-TWIN-THERMAL-*).
#pragma once
#include "twin/specs.hpp"

namespace sreh {

// Calibrated to behaviour, not to a drawing (A-TWIN-THERMAL-1..4): the
// motor model's copper losses are small (R = 0.54 ohm, A-MOTOR-2: ~1.1 W
// mean when cycling 180 deg with 15'000 g cm^2 and no dwell, ~0.1 W for
// normal duty), so the sensed hot spot sits behind a high resistance.
struct ThermalConstants {
  double winding_capacity_J_per_K = 2.5;    // winding + power stage hot spot the sensor sees
  double housing_capacity_J_per_K = 150.0;  // aluminium housing + flange (~0.17 kg)
  double winding_to_housing_K_per_W = 50.0; // tau = 125 s
  double housing_to_ambient_K_per_W = 8.0;  // free convection, tau = 20 min
  double speed_loss_W_per_rad_s = 0.004;    // iron + bearing losses: 0.3 W at 4300 deg/s
};

class Thermal {
 public:
  explicit Thermal(const ThermalSpec& spec, const ThermalConstants& constants = {});

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
  ThermalSpec spec_;
  ThermalConstants constants_;
  double winding_C_;
  double housing_C_;
};

} // namespace sreh
