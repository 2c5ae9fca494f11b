// Trace of a twin run: one row per IO-Link cycle (interfaces.md "Trace").
// Plain data; twin/ records it, renders/ and scenarios/ read it.
#pragma once
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "device_logic/device_types.hpp"
#include "device_logic/process_data.hpp"

namespace sreh {

struct TraceRow {
  double t_s = 0;
  State state = State::MotorOff;
  double setpoint_deg = 0;
  double position_deg = 0;
  double tracking_error_deg = 0;
  double velocity_dps = 0;
  double torque_Nm = 0;        // motor torque applied
  double torque_limit_Nm = 0;  // motor capability in that direction at that instant
  double external_torque_Nm = 0;
  double supply_V = 0;
  double temperature_C = 0;
  uint8_t error_code = 0;
  uint8_t warning_code = 0;
  PdOutFrame pd_out{};
  PdInFrame pd_in{};
  LedColor led = LedColor::Off;
  IoLinkLedMode iolink_led = IoLinkLedMode::NotConnected; // manual 1
};

// One executed move command (interfaces.md `moves`), manual 3.5.2 terms.
struct MoveRecord {
  double start_s = 0;          // Move accepted (point a)
  double travel_s = 0;         // (1) duration of the target trajectory
  double settling_s = 0;       // (2) from trajectory end (b) to completion (f), >= 0; <0 if never completed
  double positioning_s = 0;    // (4) travel + settling (>= travel); <0 if never completed
  double max_tracking_error_deg = 0;
  double overshoot_deg = 0;    // furthest past the target in the direction of travel, from (b) until the next move (>= 0)
  double in_window_s = -1;     // from (b) until the position entered the tolerance window for good (servo.md),
                               // while the target is held; <0: outside the window when the move's record ended
  double target_deg = 0;
  bool completed = false;      // reached Done (false: stopped, error, SettlingTimeout 114.8)
};

// Writes the CSV header and rows (interfaces.md column order first).
void write_trace_csv(std::ostream& out, const std::vector<TraceRow>& rows);

} // namespace sreh
