// The motor's power stage with its current loop and the winding (issue 14,
// issue 25): once per control period the current controller samples the
// winding current and sets the bridge voltage for the period (PI tuned on
// the winding's R and L by pole-zero cancellation, bandwidth w_c, back-EMF
// feed-forward, limited to the bus voltage); the winding
// L di/dt = u - R i - ke w is then integrated exactly over each physics
// sub-step with that voltage held (a PWM bridge's mean voltage) and the
// back-EMF of the sub-step. The speed limit of manual 3.5.3 follows from the
// voltage limit: at speed w no more current than (U - ke w) / R flows.
// The controller's clock is the drive's; the sub-steps are the simulator's.
// Constants: the model card (A-MOTOR-1..4, A-CTRL-6); the controller is
// tuned on the firmware's motor (nominal constants), the winding runs on
// the module's (issue 36, A-CAL-11).
#pragma once
#include "device_logic/motor_model.hpp"

namespace sreh {

class MotorDrive {
 public:
  // `motor`: the module's winding and torque constant; `firmware`: what
  // the controller is tuned on (twin/firmware_motor.hpp).
  MotorDrive(const MotorModel& motor, const MotorModel& firmware, double control_period_s, double physics_dt_s);

  // Once per control period: the current reference from `torque_ref_Nm`
  // (clamped to the current limit), the rotor speed and the bus voltage now.
  // `enabled` false: the bridge is off, the current decays through the
  // freewheel diodes (modelled as a short, integrator cleared).
  void control(double torque_ref_Nm, bool enabled, double rotor_speed_rad_s, double bus_V);
  // One physics sub-step with the period's voltage and this rotor speed.
  void advance(double rotor_speed_rad_s);

  double current_A() const { return i_A_; }                 // at the end of the sub-step
  double mean_torque_Nm() const { return mean_torque_Nm_; } // kt x mean current over the sub-step
  double mean_current_A() const { return mean_i_A_; }
  double voltage_V() const { return u_V_; }                 // bridge voltage over the period
  bool enabled() const { return enabled_; }
  void reset() { i_A_ = 0; integral_V_ = 0; u_V_ = 0; mean_i_A_ = 0; mean_torque_Nm_ = 0; }

 private:
  MotorModel motor_;    // the plant's
  MotorModel firmware_; // the controller's
  double control_period_s_;
  double kp_V_per_A_;  // L w_c (the firmware's L)
  double ki_V_per_As_; // R w_c (the firmware's R)
  double decay_;       // exp(-R dt / L) over one sub-step
  double mean_factor_; // (L / R) / dt (1 - decay): mean of the exponential over a sub-step
  bool enabled_ = false;
  double i_A_ = 0;
  double integral_V_ = 0;
  double u_V_ = 0;
  double mean_i_A_ = 0;
  double mean_torque_Nm_ = 0;
};

} // namespace sreh
