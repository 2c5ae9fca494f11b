// The motor's torque capability: a DC-type motor with back-EMF and a current
// limit. The manual gives only M = 0.485 N m (3.5.4) and that the reachable
// speed falls in proportion to the supply voltage below 24 V (3.5.3); every
// constant here is an assumption, listed in ASSUMPTIONS.md (A-MOTOR-*).
#pragma once
#include <algorithm>
#include <cmath>

#include "device_logic/units.hpp"

namespace sreh {

struct MotorModel {
  // A-MOTOR-1: back-EMF / torque constant (flange side). No-load speed
  // 24 V / ke = 4400 deg/s at 24 V and proportional to the voltage below
  // (manual 3.5.3: "the maximum possible speed decreases proportionally to
  // the voltage", 4300 deg/s at 24 V): at 19 V nothing above 3483 deg/s is
  // reachable, so 3500 deg/s ends in a tracking error and 3300 completes.
  double torque_constant_Nm_per_A = 24.0 / deg_to_rad(4400.0);
  // A-MOTOR-2: winding resistance 0.543 ohm (kept from issue 5: the thermal
  // model is calibrated on its copper losses). Full peak torque up to
  // ~4200 deg/s at 24 V, 0.31 N m left at 4300 deg/s for the end of the
  // S-curve's acceleration; at 19 V the rated M = 0.485 N m up to 3330 deg/s.
  double winding_resistance_ohm = 0.543;
  // A-MOTOR-3: current limit of the output stage; peak torque 0.60 N m, i.e.
  // 24 % above M so the controller keeps headroom at full acceleration.
  double current_limit_A = 0.60 / (24.0 / deg_to_rad(4400.0));
  // A-MOTOR-4: winding inductance 1.0 mH (electrical time constant L/R =
  // 1.8 ms), the order of comparable small servo motors' phase inductance.
  double winding_inductance_H = 1.0e-3;
  // A-CTRL-6: current loop bandwidth 2 pi x 1 kHz (PI on R and L).
  double current_loop_bandwidth_rad_s = 2.0 * kPi * 1000.0;

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
