// What the firmware knows of its own drive: the motor's data, the loop
// tuning and the drive's clocks. Every value comes from the module's model
// card (models/sreh50-model.yaml, read by twin/model_card.cpp): the device
// logic holds no physical constant of its own and reads no file.
#pragma once
#include <cstdint>

#include "device_logic/motor_model.hpp"
#include "device_logic/position_controller.hpp"

namespace sreh {

struct DriveModel {
  MotorModel motor;
  ControllerGains gains;
  // The control period (A-CTRL-8): planner setpoint, position/velocity loop,
  // current loop and monitors run once per period, whatever a simulator's
  // step; tick() is called once per period.
  int64_t control_period_ns = 0;
  double speed_filter_s = 0; // A-MON-3: the speed estimate of the monitors and the torque-speed limit

  double control_period_s() const { return static_cast<double>(control_period_ns) * 1e-9; }
  bool operator==(const DriveModel&) const = default;
};

} // namespace sreh
