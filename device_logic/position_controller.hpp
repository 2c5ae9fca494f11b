// Position control with velocity and acceleration feed-forward, using the
// configured inertia (architecture.md), torque saturated to what the motor
// can give now, with anti-windup. Gains are assumptions (ASSUMPTIONS.md).
#pragma once
#include "device_logic/planner.hpp"

namespace sreh {

struct ControllerGains {
  double bandwidth_rad_s = 0;  // position loop bandwidth (set in the .cpp defaults)
  double damping = 0;
  double integral_ratio = 0;   // integral corner as a fraction of the bandwidth
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
  double update(const KinematicState& setpoint, double measured_pos_rad, double inertia_kgm2,
                double torque_limit_pos_Nm, double torque_limit_neg_Nm, double dt_s);

  double velocity_estimate_rad_s() const { return vel_est_; }

 private:
  ControllerGains gains_;
  double last_pos_ = 0;
  double vel_est_ = 0;
  double integral_ = 0;
  bool primed_ = false;
};

} // namespace sreh
