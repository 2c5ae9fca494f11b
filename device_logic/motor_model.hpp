// The motor's torque capability: a DC-type motor with back-EMF and a current
// limit. The manual gives only M = 0.485 N m (3.5.4) and that the reachable
// speed falls in proportion to the supply voltage below 24 V (3.5.3); every
// constant is an assumption on the model card (A-MOTOR-*).
#pragma once
#include <algorithm>
#include <cmath>

#include "device_logic/units.hpp"

namespace sreh {

struct MotorModel {
  // The constants come from the model card (models/sreh50-model.yaml, read by
  // twin/model_card.cpp); their reasons are A-MOTOR-1..4 and A-CTRL-6.
  double torque_constant_Nm_per_A = 0; // = back-EMF constant (V s/rad), flange side
  double winding_resistance_ohm = 0;
  double current_limit_A = 0;          // of the output stage: the peak torque is kt x this
  double winding_inductance_H = 0;
  double current_loop_bandwidth_rad_s = 0;

  bool operator==(const MotorModel&) const = default;

  double peak_torque_Nm() const { return torque_constant_Nm_per_A * current_limit_A; }

  // Largest torque magnitude the output stage can produce in direction
  // `sign_of_torque` (+1/-1) at this flange speed and supply voltage.
  // Motoring (torque along the velocity) is limited by the back-EMF:
  //   I = (U - ke*w) / R.  Braking is limited by the current limit only.
  double max_torque_Nm(double velocity_rad_s, double supply_V, double sign_of_torque) const {
    const double kt = torque_constant_Nm_per_A;
    const double peak = peak_torque_Nm();
    const double motoring_speed = velocity_rad_s * sign_of_torque; // > 0 when motoring
    if (motoring_speed <= 0.0) {
      // Braking / plugging: the bridge can still drive I up to the limit as
      // long as U + ke*|w| pushes it; the current limit binds first.
      return peak;
    }
    const double current = (supply_V - kt * motoring_speed) / winding_resistance_ohm;
    return std::clamp(kt * current, 0.0, peak);
  }

  // Clamps a requested torque to what the motor can produce now.
  double saturate(double torque_Nm, double velocity_rad_s, double supply_V) const {
    const double sign = torque_Nm >= 0.0 ? 1.0 : -1.0;
    const double limit = max_torque_Nm(velocity_rad_s, supply_V, sign);
    return std::clamp(torque_Nm, -limit, limit);
  }

  // Winding current for a torque (magnitude), and the copper loss it causes.
  double current_A(double torque_Nm) const { return std::abs(torque_Nm) / torque_constant_Nm_per_A; }
  double copper_loss_W(double torque_Nm) const {
    const double i = current_A(torque_Nm);
    return i * i * winding_resistance_ohm;
  }
};

} // namespace sreh
