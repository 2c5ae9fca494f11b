// Position control with velocity and acceleration feed-forward, using the
// configured inertia (architecture.md), torque saturated to what the motor
// can give now, with anti-windup. Gains are assumptions (docs/assumptions/
// motion.md A-CTRL-*).
//
//   torque = J * (acc_sp + Kv de/dt + Kp e) + I,   e = pos_sp - pos,
//   dI/dt  = J * Ki e,   J = J_intern + configured load.
// de/dt is the encoder-difference estimate of the error rate, low-passed;
// the setpoint goes through the same difference and filter as the encoder,
// so the filter lag does not turn the velocity feed-forward into a bias.
// Kv, Kp, Ki place the closed-loop poles of a rigid inertia at
// (s + wi)(s^2 + 2 zeta w s + w^2), wi = integral_ratio * w: the loop is the
// same for every load when the configured load is right, and detuned (slow,
// oscillating, or saturating) when it is wrong, as on the real module.
#pragma once
#include "device_logic/planner.hpp"

namespace sreh {

struct ControllerGains {
  double bandwidth_rad_s = 0;  // position loop bandwidth (set in the .cpp defaults)
  double damping = 0;
  double integral_ratio = 0;   // integral corner as a fraction of the bandwidth
  double velocity_filter_s = 0; // time constant of the low-pass on the encoder difference

  // Loop gains per unit inertia (rad/s^2 per rad/s, per rad, per rad s).
  double kv_per_s() const { return 2.0 * damping * bandwidth_rad_s + integral_ratio * bandwidth_rad_s; }
  double kp_per_s2() const { return bandwidth_rad_s * bandwidth_rad_s * (1.0 + 2.0 * damping * integral_ratio); }
  double ki_per_s3() const { return bandwidth_rad_s * bandwidth_rad_s * bandwidth_rad_s * integral_ratio; }
};
ControllerGains default_controller_gains();

class PositionController {
 public:
  explicit PositionController(ControllerGains gains = default_controller_gains());

  // Forget integrator and velocity filter; `measured_pos_rad` is the position now.
  void reset(double measured_pos_rad);

  // One control step. `setpoint` from the planner (pos/vel/acc in rad),
  // `measured_pos_rad` from the encoder, `inertia_kgm2` = J_intern + configured
  // load, `torque_limit_pos_Nm` / `torque_limit_neg_Nm` the motor's capability
  // in each direction now (both >= 0). Returns the saturated torque.
  // Not reset yet: the first call resets at `measured_pos_rad`. dt_s <= 0 or a
  // non-finite input: no state change, returns 0 torque.
  double update(const KinematicState& setpoint, double measured_pos_rad, double inertia_kgm2,
                double torque_limit_pos_Nm, double torque_limit_neg_Nm, double dt_s);

  double velocity_estimate_rad_s() const { return vel_est_; }
  double integral_torque_Nm() const { return integral_; }
  bool saturated() const { return saturated_; } // the last update hit a torque limit
  const ControllerGains& gains() const { return gains_; }

 private:
  ControllerGains gains_;
  double last_pos_ = 0;
  double last_err_ = 0;
  double vel_est_ = 0;     // measured velocity, filtered
  double err_rate_ = 0;    // d(setpoint - measured)/dt, filtered
  double integral_ = 0;
  bool primed_ = false;
  bool saturated_ = false;
};

} // namespace sreh
