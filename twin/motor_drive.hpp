// The motor's power stage with its current loop and the winding (issue 14):
// the device's controller hands a torque (current) reference; a PI current
// loop tuned on the winding's R and L (pole-zero cancellation, bandwidth
// w_c, back-EMF feed-forward) drives the bridge voltage, limited to the bus
// voltage, into the winding L di/dt = u - R i - ke w, integrated exactly over
// the step. The speed limit of manual 3.5.3 follows from the voltage limit:
// at speed w no more current than (U - ke w) / R flows. Constants:
// docs/assumptions/motion.md A-MOTOR-1..5, A-CTRL-6.
#pragma once
#include "device_logic/motor_model.hpp"

namespace sreh {

class MotorDrive {
 public:
  explicit MotorDrive(const MotorModel& motor, double dt_s);

  // One step of dt_s: the current reference from `torque_ref_Nm` (clamped to
  // the current limit), the rotor speed and the bus voltage. `enabled` false:
  // the bridge is off, the current decays to 0 through the freewheel diodes
  // (modelled as u = 0 and the integrator cleared).
  void step(double torque_ref_Nm, bool enabled, double rotor_speed_rad_s, double bus_V);

  double current_A() const { return i_A_; }                 // at the end of the step
  double mean_torque_Nm() const { return mean_torque_Nm_; } // kt x mean current over the step
  double mean_current_A() const { return mean_i_A_; }
  double voltage_V() const { return u_V_; }                 // bridge voltage applied over the step
  void reset() { i_A_ = 0; integral_V_ = 0; u_V_ = 0; mean_i_A_ = 0; mean_torque_Nm_ = 0; }

 private:
  MotorModel motor_;
  double dt_s_;
  double kp_V_per_A_;  // L w_c
  double ki_V_per_As_; // R w_c
  double decay_;       // exp(-R dt / L)
  double i_A_ = 0;
  double integral_V_ = 0;
  double u_V_ = 0;
  double mean_i_A_ = 0;
  double mean_torque_Nm_ = 0;
};

} // namespace sreh
