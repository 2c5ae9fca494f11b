// Current loop and winding, A-CTRL-6 and A-MOTOR-4 (docs/assumptions/motion.md).
#include "twin/motor_drive.hpp"

#include <algorithm>
#include <cmath>

namespace sreh {

MotorDrive::MotorDrive(const MotorModel& motor, double dt_s)
    : motor_(motor),
      dt_s_(dt_s),
      kp_V_per_A_(motor.winding_inductance_H * motor.current_loop_bandwidth_rad_s),
      ki_V_per_As_(motor.winding_resistance_ohm * motor.current_loop_bandwidth_rad_s),
      decay_(std::exp(-motor.winding_resistance_ohm * dt_s / motor.winding_inductance_H)) {}

void MotorDrive::step(double torque_ref_Nm, bool enabled, double rotor_speed_rad_s, double bus_V) {
  const double r = motor_.winding_resistance_ohm;
  const double ke = motor_.torque_constant_Nm_per_A;
  const double emf_V = ke * rotor_speed_rad_s;
  const double i0 = i_A_;
  if (!enabled) {
    // Bridge off: the winding current, if any, decays through the diodes
    // against the back-EMF; modelled as a short (u = 0) until it is gone.
    integral_V_ = 0;
    u_V_ = 0;
    i_A_ = i0 == 0.0 ? 0.0 : i0 * decay_;
    if (std::abs(i_A_) < 1e-9) i_A_ = 0.0;
  } else {
    const double limit_A = motor_.current_limit_A;
    const double i_ref = std::clamp(torque_ref_Nm / ke, -limit_A, limit_A);
    const double err = i_ref - i0;
    const double u_unsat = kp_V_per_A_ * err + integral_V_ + emf_V; // back-EMF feed-forward
    const double u_max = std::max(0.0, bus_V);
    u_V_ = std::clamp(u_unsat, -u_max, u_max);
    // Anti-windup: integrate unless the bridge is at its voltage limit and
    // the error would push it further.
    const double d_int = ki_V_per_As_ * err * dt_s_;
    if (!((u_unsat > u_max && d_int > 0) || (u_unsat < -u_max && d_int < 0))) integral_V_ += d_int;
    // Exact solution of L di/dt = u - R i - e over the step (u, e held).
    const double i_inf = (u_V_ - emf_V) / r;
    i_A_ = i_inf + (i0 - i_inf) * decay_;
  }
  // Mean current over the step (exact for the exponential).
  const double tau = motor_.winding_inductance_H / r;
  const double i_inf = enabled ? (u_V_ - emf_V) / r : 0.0;
  mean_i_A_ = i_inf + (i0 - i_inf) * tau / dt_s_ * (1.0 - decay_);
  mean_torque_Nm_ = ke * mean_i_A_;
}

} // namespace sreh
