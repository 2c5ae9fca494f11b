// Cascaded position / velocity loop, manual 3.5.4-3.5.6 (configured load),
// 3.5.3 (torque-speed limit -> tracking error). Gains: A-CTRL-1..5.
#include "device_logic/position_controller.hpp"

#include <algorithm>
#include <cmath>

#include "device_logic/units.hpp"

namespace sreh {

double ControllerGains::velocity_bandwidth_for(double inertia_kgm2) const {
  const double ratio = kInternalInertia_kgm2 / std::max(inertia_kgm2, kInternalInertia_kgm2);
  return velocity_bandwidth_rad_s * std::pow(ratio, schedule_exponent);
}

PositionController::PositionController(ControllerGains gains) : gains_(gains) {}

void PositionController::reset(double measured_pos_rad) {
  last_pos_ = measured_pos_rad;
  last_sp_pos_ = measured_pos_rad;
  vel_est_ = 0.0;
  sp_vel_ = 0.0;
  integral_ = 0.0;
  pending_.fill(0.0);
  pending_head_ = 0;
  primed_ = true;
  saturated_ = false;
}

double PositionController::update(const KinematicState& setpoint, double measured_pos_rad, double inertia_kgm2,
                                  double torque_limit_pos_Nm, double torque_limit_neg_Nm, double dt_s) {
  if (!(dt_s > 0.0) || !std::isfinite(measured_pos_rad) || !std::isfinite(setpoint.pos_rad) ||
      !std::isfinite(inertia_kgm2)) {
    return 0.0;
  }
  if (!primed_) {
    reset(measured_pos_rad);
    last_sp_pos_ = setpoint.pos_rad;
    sp_vel_ = setpoint.vel_rad_s;
  }

  // Speed from encoder differences, low-passed (one count per step is
  // 0.12 rad/s at 2^19 counts/rev and 0.1 ms); the setpoint through the same.
  const double alpha = dt_s / (gains_.velocity_filter_s + dt_s);
  vel_est_ += alpha * ((measured_pos_rad - last_pos_) / dt_s - vel_est_);
  last_pos_ = measured_pos_rad;
  sp_vel_ += alpha * ((setpoint.pos_rad - last_sp_pos_) / dt_s - sp_vel_);
  last_sp_pos_ = setpoint.pos_rad;

  const double j = inertia_kgm2;
  if (j != wv_memo_.inertia_kgm2) wv_memo_ = {j, gains_.velocity_bandwidth_for(j)};
  const double wv = wv_memo_.wv_rad_s;
  const double kv = j * wv;
  const double pos_err = setpoint.pos_rad - measured_pos_rad;
  const double vel_err = sp_vel_ + gains_.position_ratio * wv * pos_err - vel_est_;
  const double hi = std::max(0.0, torque_limit_pos_Nm);
  const double lo = -std::max(0.0, torque_limit_neg_Nm);

  const double unsat = j * setpoint.acc_rad_s2 + kv * vel_err + integral_;
  const double torque = std::clamp(unsat, lo, hi);
  saturated_ = torque != unsat;

  // Anti-windup by conditional integration (A-CTRL-5): integrate unless
  // saturated and the error would drive further into the limit; keep I
  // inside the limits.
  const double d_integral = kv * gains_.integral_ratio * wv * vel_err * dt_s;
  const bool winds_up = (unsat > hi && d_integral > 0.0) || (unsat < lo && d_integral < 0.0);
  if (!winds_up) integral_ = std::clamp(integral_ + d_integral, lo, hi);

  if (gains_.delay_periods <= 0) return torque;
  const int n = std::min(gains_.delay_periods, kMaxDelayPeriods);
  const double out = pending_[static_cast<std::size_t>(pending_head_)]; // computed n periods ago (A-CTRL-7)
  pending_[static_cast<std::size_t>(pending_head_)] = torque;
  pending_head_ = (pending_head_ + 1) % n;
  return out;
}

} // namespace sreh
