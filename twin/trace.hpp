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

// One row per IO-Link cycle: the device's Telemetry as it was after the
// cycle, by value, plus what only the twin knows. Everyone downstream reads
// this one type: the CSV (write_trace_row), the video overlay (FrameInfo
// embeds it), the report and sizing (spans of rows), the Python API.
// Measured at the module, not as the firmware believes it: torque_Nm is the
// torque the plant applied (kt x winding current), supply_V and
// temperature_C the plant's sensors, led Off while unpowered.
struct TraceRow : Telemetry {
  double t_s = 0;                 // run time (sum of master cycles, integer ns)
  double external_torque_Nm = 0;  // the world's torque on the flange (physical frame)
  PdOutFrame pd_out{};            // the 6 octets the device latched this cycle (manual 2.2)
  PdInFrame pd_in{};              // the 7 octets the master received (manual 2.3)
  IoLinkLedMode iolink_led = IoLinkLedMode::NotConnected; // manual 1
};

// Move records: device_logic/move_record.hpp (the device emits them, issue 13).

// Writes the CSV header and rows (interfaces.md column order first).
void write_trace_csv(std::ostream& out, const std::vector<TraceRow>& rows);
// The same bytes in pieces, for streaming a trace while it is made:
// header once, then one call per row (write_trace_csv is exactly this).
void write_trace_header(std::ostream& out);
void write_trace_row(std::ostream& out, const TraceRow& row);

} // namespace sreh
