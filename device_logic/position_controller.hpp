// Cascaded servo control as drives are built (issue 14, servo.md):
//
//   position loop (P, with velocity feed-forward from the planner)
//     -> velocity loop (PI, with acceleration feed-forward J a)
//       -> torque (current) reference, saturated to what the motor can give
//          now, with anti-windup; handed to the current loop
//          `delay_periods` control periods later (A-CTRL-7: the encoder's
//          serial transfer, the computation, the PWM reload).
//
//   v_cmd  = v_sp~ + Kp e,           e = pos_sp - encoder
//   torque = J a_sp + Kv (v_cmd - v~) + I,   dI/dt = Kv wi (v_cmd - v~)
//
// v~ is the encoder-difference speed through a first-order filter; the
// setpoint passes through the same difference and filter (v_sp~), so the
// filter lag does not turn the feed-forward into a bias. The loop sees only
// encoder counts (2^19 per revolution): quantisation is inside the loop.
//
// Gain schedule (A-CTRL-1..3): the drive tunes for J = J_intern + the
// configured load (manual 3.5.6, index 64+n.4): Kv = J wv(J), with the
// velocity bandwidth wv falling as the configured inertia grows,
//   wv(J) = wv0 (J_intern / J)^p,
// because the delays and the two-mass resonance cap the loop gain the motor
// side can carry. Kp = wv * position_ratio, wi = wv * integral_ratio. A
// wrong configured load is a wrong plant for this loop: overshoot, ringing,
// at worst tracking errors or instability, from the dynamics alone.
#pragma once
#include <array>

#include "device_logic/planner.hpp"

namespace sreh {

// The firmware's tuning, from the model card (A-CTRL-1..4, A-CTRL-7).
struct ControllerGains {
  double velocity_bandwidth_rad_s = 0; // wv0: velocity loop bandwidth at J = J_intern
  double schedule_exponent = 0;        // p in wv(J) = wv0 (J_intern / J)^p
  double position_ratio = 0;           // position loop bandwidth / velocity loop bandwidth
  double integral_ratio = 0;           // velocity integral corner / velocity loop bandwidth
  double velocity_filter_s = 0;        // time constant of the low-pass on encoder differences
  int delay_periods = 0;                 // loop delay in control periods (0 .. 4)

  double velocity_bandwidth_for(double inertia_kgm2) const; // wv(J)
  bool operator==(const ControllerGains&) const = default;
};
class PositionController {
 public:
  static constexpr int kMaxDelayPeriods = 4; // the longest loop delay it holds (A-CTRL-7)

  PositionController() = default; // no gains yet: the device sets them from its DriveModel
  explicit PositionController(ControllerGains gains);

  // Forget integrator, filters and the delayed output; `measured_pos_rad` is the position now.
  void reset(double measured_pos_rad);

  // One control step. `setpoint` from the planner (pos/vel/acc in rad),
  // `measured_pos_rad` from the encoder, `inertia_kgm2` = J_intern + configured
  // load, `torque_limit_pos_Nm` / `torque_limit_neg_Nm` the motor's capability
  // in each direction now (both >= 0). Returns the torque reference for the
  // current loop: the saturated output computed `delay_periods` periods ago.
  // Not reset yet: the first call resets at `measured_pos_rad`. dt_s <= 0 or a
  // non-finite input: no state change, returns 0 torque.
  double update(const KinematicState& setpoint, double measured_pos_rad, double inertia_kgm2,
                double torque_limit_pos_Nm, double torque_limit_neg_Nm, double dt_s);

  double velocity_estimate_rad_s() const { return vel_est_; }
  double integral_torque_Nm() const { return integral_; }
  bool saturated() const { return saturated_; } // the last computed output hit a torque limit
  const ControllerGains& gains() const { return gains_; }
  bool operator==(const PositionController&) const = default;

 private:
  ControllerGains gains_;
  double last_pos_ = 0;
  double last_sp_pos_ = 0;
  double vel_est_ = 0;     // measured velocity, filtered
  double sp_vel_ = 0;      // setpoint velocity through the same difference and filter
  double integral_ = 0;
  std::array<double, kMaxDelayPeriods> pending_{}; // outputs of the last periods (loop delay, A-CTRL-7)
  int pending_head_ = 0;
  bool primed_ = false;
  // wv(J) for the inertia of the last call: J changes only with the
  // configured load, and the pow() of every step was ~2 % of a sizing run's
  // CPU. A cache of a pure function, not state: equal whatever it holds.
  struct BandwidthMemo {
    double inertia_kgm2 = -1;
    double wv_rad_s = 0;
    bool operator==(const BandwidthMemo&) const { return true; }
  };
  BandwidthMemo wv_memo_;
  bool saturated_ = false;
};

} // namespace sreh
