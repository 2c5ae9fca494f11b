// Position loop with feed-forward, manual 3.5.4-3.5.6 (configured load),
// 3.5.3 (torque-speed limit -> tracking error). Gains: A-CTRL-1..4.
#include "device_logic/position_controller.hpp"

#include <algorithm>
#include <cmath>

namespace sreh {

ControllerGains default_controller_gains() {
  ControllerGains g;
  g.bandwidth_rad_s = 500.0;    // A-CTRL-1
  g.damping = 0.8;              // A-CTRL-2
  g.integral_ratio = 0.3;       // A-CTRL-3
  g.velocity_filter_s = 0.3e-3; // A-CTRL-4
  return g;
}

PositionController::PositionController(ControllerGains gains) : gains_(gains) {}

void PositionController::reset(double measured_pos_rad) {
  last_pos_ = measured_pos_rad;
  last_err_ = 0.0;
  vel_est_ = 0.0;
  err_rate_ = 0.0;
  integral_ = 0.0;
  primed_ = true;
  saturated_ = false;
}

double PositionController::update(const KinematicState& setpoint, double measured_pos_rad, double inertia_kgm2,
                                  double torque_limit_pos_Nm, double torque_limit_neg_Nm, double dt_s) {
  if (!(dt_s > 0.0) || !std::isfinite(measured_pos_rad) || !std::isfinite(setpoint.pos) ||
      !std::isfinite(inertia_kgm2)) {
    return 0.0;
  }
  if (!primed_) {
    reset(measured_pos_rad);
    last_err_ = setpoint.pos - measured_pos_rad;
  }

  // Velocity from encoder differences, low-passed (the raw quotient jumps by
  // one count / dt = 0.12 rad/s at 2^19 counts/rev and 0.1 ms).
  const double raw_vel = (measured_pos_rad - last_pos_) / dt_s;
  last_pos_ = measured_pos_rad;
  const double alpha = dt_s / (gains_.velocity_filter_s + dt_s);
  vel_est_ += alpha * (raw_vel - vel_est_);

  const double j = inertia_kgm2;
  const double pos_err = setpoint.pos - measured_pos_rad;
  err_rate_ += alpha * ((pos_err - last_err_) / dt_s - err_rate_);
  last_err_ = pos_err;
  const double vel_err = err_rate_;
  const double hi = std::max(0.0, torque_limit_pos_Nm);
  const double lo = -std::max(0.0, torque_limit_neg_Nm);

  const double unsat = j * (setpoint.acc + gains_.kv_per_s() * vel_err + gains_.kp_per_s2() * pos_err) + integral_;
  const double torque = std::clamp(unsat, lo, hi);
  saturated_ = torque != unsat;

  // Anti-windup by conditional integration: integrate unless saturated and
  // the error would drive further into the limit; keep I inside the limits.
  const double d_integral = j * gains_.ki_per_s3() * pos_err * dt_s;
  const bool winds_up = (unsat > hi && d_integral > 0.0) || (unsat < lo && d_integral < 0.0);
  if (!winds_up) integral_ = std::clamp(integral_ + d_integral, lo, hi);
  return torque;
}

} // namespace sreh
