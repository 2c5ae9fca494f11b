// Firmware and module apart (issue 36, A-CAL-11): the motor constants the
// firmware was built for are the shipped card's, not the module's. Its
// current loop (PI on L and R by pole-zero cancellation), current reference
// (torque / kt), back-EMF feed-forward (kt w) and torque limits use these;
// the plant's winding and torque use the module's (the model file given). A
// module whose motor differs from nominal then meets a firmware tuned for
// nominal, as a real one does. The firmware's own settings (current limit,
// current-loop bandwidth, loop gains, clocks) stay the module's: they are
// what its firmware is configured with.
#pragma once
#include "device_logic/drive_model.hpp"

namespace sreh {

struct NominalMotor {
  double torque_constant_Nm_per_A = 0;
  double winding_resistance_ohm = 0;
  double winding_inductance_H = 0;
  bool operator==(const NominalMotor&) const = default;
};

// The motor constants of `motor` (of the card, or of a module).
NominalMotor nominal_motor_of(const MotorModel& motor);

// The drive as the firmware knows it: `module`'s with the motor's constants
// replaced by `nominal`'s.
DriveModel firmware_drive(const DriveModel& module, const NominalMotor& nominal);

} // namespace sreh
