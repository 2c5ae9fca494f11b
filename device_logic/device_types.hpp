// Plain types at the Device boundary: what a plant hands in each control
// step, what the device hands back, and what a renderer or trace may show.
#pragma once
#include <cstdint>
#include <string_view>
#include <vector>

namespace sreh {

// Manual 3.1. Names print exactly as interfaces.md says.
enum class State : uint8_t { MotorOff, Ready, Busy, Done, ErrorOn, ErrorOff };
std::string_view state_name(State s);

// Sensor readings a plant hands the device every control step.
struct SensorReadings {
  // Absolute flange angle of the encoder, 2^19 counts per revolution,
  // physical frame: positive = clockwise seen from above (manual 4.2,
  // factory positive direction). Multiturn, never wrapped; the device itself
  // only keeps what a 4-revolution absolute encoder keeps (manual 4.1).
  int64_t encoder_counts = 0;
  double supply_V = 24.0;      // motor voltage, pins 2 and 5 (manual 6.4, index 113)
  double temperature_C = 25.0; // module temperature sensor (index 112)
};

// What the device asks of the motor this control step.
struct MotorCommand {
  double torque_Nm = 0.0; // physical frame (same sign convention as encoder_counts)
  bool enabled = false;   // output stage on (motor energised)
};

// LED band colour at an instant (manual 3.1, index 83, 6.6 locator, 9 boot mode).
enum class LedColor : uint8_t { Off, Green, Yellow, Blue, Red, Orange, White, Violet };
std::string_view led_name(LedColor c);

// IO-Link status LED next to the connector (manual 1).
enum class IoLinkLedMode : uint8_t { NotConnected, Startup, Preoperate, Operate };
std::string_view iolink_led_name(IoLinkLedMode m); // "off", "startup", "preoperate", "operate"

// Where the master has taken the device's communication since power-on
// (IO-Link 1.1.3: STARTUP, PREOPERATE, OPERATE; A-LINK-3).
enum class ComPhase : uint8_t { Startup, Preoperate, Operate };

// A snapshot for traces and renderers; the PLC never sees this.
struct Telemetry {
  State state = State::MotorOff;
  double setpoint_deg = 0;        // planned setpoint in process-data degrees (after zero offset and direction)
  double position_deg = 0;        // actual position in process-data degrees
  double tracking_error_deg = 0;  // setpoint - actual while a trajectory runs or settles
  double velocity_dps = 0;        // estimated, process-data direction
  double torque_Nm = 0;           // commanded motor torque, physical frame
  double torque_limit_Nm = 0;     // what the motor could give in that direction now
  double supply_V = 0;
  double temperature_C = 0;
  uint8_t error_code = 0;         // bit field, manual 2.4
  uint8_t warning_code = 0;
  LedColor led = LedColor::Off;
  bool moving = false;            // a trajectory is being followed (travel phase)
  bool settling = false;          // trajectory ended, waiting for the tolerance window
  uint32_t moves_started = 0;     // Move commands accepted (T3) since power-on
  double tolerance_deg = 0;       // tolerance window half width of the latched set (manual 3.5.7)
};

} // namespace sreh
