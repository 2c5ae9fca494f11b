#include "twin/firmware_motor.hpp"

namespace sreh {

NominalMotor nominal_motor_of(const MotorModel& motor) {
  return {motor.torque_constant_Nm_per_A, motor.winding_resistance_ohm, motor.winding_inductance_H};
}

DriveModel firmware_drive(const DriveModel& module, const NominalMotor& nominal) {
  DriveModel d = module;
  d.motor.torque_constant_Nm_per_A = nominal.torque_constant_Nm_per_A;
  d.motor.winding_resistance_ohm = nominal.winding_resistance_ohm;
  d.motor.winding_inductance_H = nominal.winding_inductance_H;
  return d;
}

} // namespace sreh
