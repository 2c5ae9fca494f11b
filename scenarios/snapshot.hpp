// What a scenario can check at an instant: the PLC's view (process data in,
// manual 2.3) plus the world's (LED band, temperature, supply, motion).
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "device_logic/process_data.hpp"
#include "scenarios/scenario.hpp"
#include "twin/twin.hpp"

namespace sreh {

struct Snapshot {
  double t_s = 0;
  ProcessDataIn in;  // last frame the master received
  Telemetry telemetry;
  State state = State::MotorOff; // from the status bits of `in` (manual 3.1 table)
  double position_deg = 0;       // from `in`, 2^16 counts per 360 deg
  IoLinkLedMode iolink_led = IoLinkLedMode::NotConnected; // manual 1
};

// State as the PLC reads it from the status bits; `fallback` where the bits
// name no state (before the first frame).
State state_from_status_bits(const ProcessDataIn& in, State fallback);
Snapshot take_snapshot(const Twin& twin);

struct Evaluation {
  bool passed = true;
  std::string expected; // "state Done, position_deg [89.9, 90.1]"
  std::string actual;   // the same quantities as observed
  std::string mismatch; // only the failing ones: "state Busy (want Done)"
};

// `vars`: values saved earlier in the run, for $NAME comparisons.
Evaluation evaluate(const Conditions& c, const Snapshot& s, const Variables& vars = {});

// The numeric condition quantities a `save` step can remember, by key
// ("position_deg", ...); nullopt for a key that is not one.
std::optional<double> quantity(std::string_view key, const Snapshot& s);
inline constexpr std::string_view kSavableQuantities[] = {"position_deg", "position_raw", "error_code", "warning_code",
                                                          "temperature_C", "supply_V", "velocity_dps",
                                                          "tracking_error_deg"};

} // namespace sreh
