// Current loop and winding, A-CTRL-6 and A-MOTOR-4 (docs/assumptions/motion.md).
#include "twin/motor_drive.hpp"

#include <algorithm>
#include <cmath>

namespace sreh {

MotorDrive::MotorDrive(const MotorModel& motor, const MotorModel& firmware, double control_period_s,
                       double physics_dt_s)
    : motor_(motor),
      firmware_(firmware),
      control_period_s_(control_period_s),
      kp_V_per_A_(firmware.winding_inductance_H * firmware.current_loop_bandwidth_rad_s),
      ki_V_per_As_(firmware.winding_resistance_ohm * firmware.current_loop_bandwidth_rad_s),
      decay_(std::exp(-motor.winding_resistance_ohm * physics_dt_s / motor.winding_inductance_H)),
      mean_factor_(motor.winding_inductance_H / motor.winding_resistance_ohm / physics_dt_s * (1.0 - decay_)) {}

void MotorDrive::control(double torque_ref_Nm, bool enabled, double rotor_speed_rad_s, double bus_V) {
  enabled_ = enabled;
  if (!enabled) {
    integral_V_ = 0;
    u_V_ = 0;
    return;
  }
  // The firmware's view: its kt for the current reference and the back-EMF
  // feed-forward, its current limit.
  const double ke = firmware_.torque_constant_Nm_per_A;
  const double emf_V = ke * rotor_speed_rad_s;
  const double limit_A = firmware_.current_limit_A;
  const double i_ref = std::clamp(torque_ref_Nm / ke, -limit_A, limit_A);
  const double err = i_ref - i_A_;
  const double u_unsat = kp_V_per_A_ * err + integral_V_ + emf_V; // back-EMF feed-forward
  const double u_max = std::max(0.0, bus_V);
  u_V_ = std::clamp(u_unsat, -u_max, u_max);
  // Anti-windup: integrate unless the bridge is at its voltage limit and
  // the error would push it further.
  const double d_int = ki_V_per_As_ * err * control_period_s_;
  if (!((u_unsat > u_max && d_int > 0) || (u_unsat < -u_max && d_int < 0))) integral_V_ += d_int;
}

void MotorDrive::advance(double rotor_speed_rad_s) {
  const double i0 = i_A_;
  double i_inf = 0.0;
  if (enabled_) {
    // Exact solution of L di/dt = u - R i - e over the sub-step (u, e held).
    i_inf = (u_V_ - motor_.torque_constant_Nm_per_A * rotor_speed_rad_s) / motor_.winding_resistance_ohm;
    i_A_ = i_inf + (i0 - i_inf) * decay_;
  } else {
    // Bridge off: the winding current, if any, decays through the diodes
    // against the back-EMF; modelled as a short (u = 0) until it is gone.
    i_A_ = i0 == 0.0 ? 0.0 : i0 * decay_;
    if (std::abs(i_A_) < 1e-9) i_A_ = 0.0;
  }
  mean_i_A_ = i_inf + (i0 - i_inf) * mean_factor_; // exact mean of the exponential
  mean_torque_Nm_ = motor_.torque_constant_Nm_per_A * mean_i_A_;
}

} // namespace sreh
