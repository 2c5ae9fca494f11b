// The Device's monitors (manual 5, 6.3, 6.6, 7.2, 7.3): small values with a
// step function each, in the style of the rest of device_logic: the caller
// hands in what the monitor watches, the monitor keeps only its own memory
// (debounce timers, sub-minute remainders) and hands back a verdict; the
// Device turns verdicts into errors, warnings and counter updates. Volatile:
// a power cycle starts them afresh. Timing constants: ASSUMPTIONS.md.
#pragma once
#include <algorithm>
#include <cstdint>

#include "device_logic/faults.hpp"

namespace sreh {

inline constexpr int64_t kNsPerS = 1'000'000'000;
inline constexpr int64_t kMinute_ns = 60 * kNsPerS;

// Communication watchdog (manual 5, A-LINK-1): a link silent for longer than
// max(20 ms, 3 master cycles) is interrupted.
inline constexpr int64_t kLinkWatchdogMin_ns = 20'000'000;   // A-LINK-1: at least 20 ms ...
inline constexpr int kLinkWatchdogCycles = 3;                 // ... and at least 3 master cycles
inline constexpr int64_t kDefaultMasterCycle_ns = 2'000'000;  // manual 1: minimum cycle time 2 ms
struct LinkWatchdog {
  int64_t master_cycle_ns = kDefaultMasterCycle_ns; // MasterCycleTime the master announced
  int64_t since_exchange_ns = 0;
  bool link_up = false; // cycles arriving (watchdog not expired)

  void feed() { since_exchange_ns = 0, link_up = true; } // a master cycle arrived
  int64_t timeout_ns() const { return std::max(kLinkWatchdogMin_ns, kLinkWatchdogCycles * master_cycle_ns); }
  // One control step; true exactly once when the link is lost (it was up and
  // the silence now exceeds the timeout).
  bool step(int64_t dt_ns) {
    since_exchange_ns += dt_ns;
    if (!link_up || since_exchange_ns <= timeout_ns()) return false;
    link_up = false;
    return true;
  }
  bool operator==(const LinkWatchdog&) const = default;
};

// Motor voltage (manual 6.2 index 85, 7.2 114.4, 7.3 115.2), debounced
// (A-MON-1): the supply must stay on one side outside the range this long.
inline constexpr int64_t kVoltageDebounce_ns = 2'000'000;
struct VoltageMonitor {
  int64_t out_ns = 0; // how long the supply has been outside with `cause`
  uint8_t cause = 0;  // cause::kVoltageLow / kVoltageHigh, 0 inside the range

  // The cause code once the supply has been outside [min_V, max_V] for the
  // debounce time, else 0.
  uint8_t step(double supply_V, double min_V, double max_V, int64_t dt_ns) {
    uint8_t code = 0;
    if (supply_V < min_V) code = cause::kVoltageLow;
    else if (supply_V > max_V) code = cause::kVoltageHigh;
    if (code != 0 && code == cause) out_ns += dt_ns;
    else out_ns = 0;
    cause = code;
    return code != 0 && out_ns >= kVoltageDebounce_ns ? code : 0;
  }
  bool operator==(const VoltageMonitor&) const = default;
};

// Temperature (manual 7.2 114.3 >= 75 C, 7.3 115.1 >= 70 C, A-MON-2
// hysteresis). No memory of its own: the hysteresis state is the warning
// itself, which the caller hands in.
inline constexpr double kTemperatureWarning_C = 70.0;
inline constexpr double kTemperatureError_C = 75.0;
inline constexpr double kTemperatureHysteresis_C = 1.0;
struct TemperatureMonitor {
  struct Verdict {
    bool over_temperature = false; // 114.3
    bool warning = false;          // 115.1 on after this step
  };
  static Verdict step(double temperature_C, bool warning_now) {
    Verdict v;
    v.over_temperature = temperature_C >= kTemperatureError_C;
    if (temperature_C >= kTemperatureWarning_C) v.warning = true;
    else if (temperature_C < kTemperatureWarning_C - kTemperatureHysteresis_C) v.warning = false;
    else v.warning = warning_now;
    return v;
  }
  bool operator==(const TemperatureMonitor&) const = default;
};

// Tracking error (manual 6.2 index 87, 7.2 114.5; issue 16: setpoint minus
// encoder reading, every control step, the one definition).
inline constexpr double kTrackingErrorRawUnit_deg = 0.1; // A-PARAM-1: raw unit of index 87.1
struct TrackingMonitor {
  double step_error_deg = 0; // |setpoint - encoder| of this control step (0 with the motor off)
  double peak_error_deg = 0; // the largest step error since the last take

  // One control step with the motor on; true: the error exceeds the limit
  // while monitoring is active (114.5).
  bool step(double error_deg, double limit_deg, bool active) {
    step_error_deg = error_deg;
    peak_error_deg = std::max(peak_error_deg, error_deg);
    return active && error_deg > limit_deg;
  }
  void idle() { step_error_deg = 0; } // a step with the motor off: no setpoint
  double take_peak() {
    const double p = peak_error_deg;
    peak_error_deg = 0;
    return p;
  }
  bool operator==(const TrackingMonitor&) const = default;
};

// Persistent diagnostics (manual 6.3, index 97, 100): operating times in
// whole minutes; the sub-minute remainders live here.
struct DiagnosticsClock {
  int64_t powered_rem_ns = 0, motor_on_rem_ns = 0, moving_rem_ns = 0, temp_warn_rem_ns = 0;

  struct Minutes {
    int64_t powered = 0, motor_on = 0, moving = 0, temp_warning = 0; // whole minutes completed this step
  };
  Minutes step(int64_t dt_ns, bool motor_on, bool moving, bool temp_warning) {
    Minutes m;
    m.powered = count(powered_rem_ns, dt_ns);
    if (motor_on) m.motor_on = count(motor_on_rem_ns, dt_ns);
    if (moving) m.moving = count(moving_rem_ns, dt_ns);
    if (temp_warning) m.temp_warning = count(temp_warn_rem_ns, dt_ns);
    return m;
  }
  bool operator==(const DiagnosticsClock&) const = default;

 private:
  static int64_t count(int64_t& rem_ns, int64_t dt_ns) {
    rem_ns += dt_ns;
    int64_t whole = 0;
    while (rem_ns >= kMinute_ns) rem_ns -= kMinute_ns, ++whole; // no division on the common path
    return whole;
  }
};

// Locator (manual 6.6, commands 126/127): the LED band flashes white and
// stops by itself after 10 minutes.
inline constexpr int64_t kLocatorDuration_ns = 600 * kNsPerS;
struct Locator {
  bool active = false;
  int64_t start_ns = 0;

  void start(int64_t now_ns) { active = true, start_ns = now_ns; }
  void stop() { active = false; }
  void step(int64_t now_ns) {
    if (active && now_ns - start_ns >= kLocatorDuration_ns) active = false;
  }
  bool operator==(const Locator&) const = default;
};

// All of them, as the Device keeps them.
struct DeviceMonitors {
  LinkWatchdog link;
  VoltageMonitor voltage;
  TemperatureMonitor temperature;
  TrackingMonitor tracking;
  DiagnosticsClock diagnostics;
  Locator locator;
  bool operator==(const DeviceMonitors&) const = default;
};

} // namespace sreh
