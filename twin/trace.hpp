// Trace of a twin run: one row per IO-Link cycle (interfaces.md "Trace").
// Plain data; twin/ records it, renders/ and scenarios/ read it.
#pragma once
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "device_logic/device_types.hpp"
#include "device_logic/move_record.hpp"
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

// Move records: device_logic/move_record.hpp (the device emits them, issue 13).


// Writes the CSV header and rows (interfaces.md column order first).
void write_trace_csv(std::ostream& out, const std::vector<TraceRow>& rows);

} // namespace sreh
