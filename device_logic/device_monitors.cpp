// Monitors and indicators of the Device: temperature and motor voltage
// (manual 7.2, 7.3, index 85), locator timeout (6.6), persistent diagnostics
// (6.3), the tracking limit (index 87) and the LED band (3.1, index 83).
#include <algorithm>
#include <cmath>

#include "device_logic/device_impl.hpp"

namespace sreh {
void Device::Impl::run_monitors(int64_t dt_ns) {
  // Temperature (manual 7.2 114.3, 7.3 115.1); the warning clears itself.
  if (temperature_C >= kTemperatureError_C && faults.error(ErrorBit::Temperature) == 0) {
    raise_error(ErrorBit::Temperature, cause::kOverTemperature);
  }
  if (temperature_C >= kTemperatureWarning_C) {
    set_warning(WarningBit::Temperature, cause::kTemperatureWarning);
  } else if (temperature_C < kTemperatureWarning_C - kTemperatureHysteresis_C) {
    set_warning(WarningBit::Temperature, 0);
  }

  // Motor voltage (manual 6.2 index 85, 7.2 114.4, 7.3 115.2): an error with
  // the motor on, a warning with it off.
  const double lo = static_cast<double>(store.raw(85, 1)) * 1e-3;
  const double hi = static_cast<double>(store.raw(85, 2)) * 1e-3;
  uint8_t code = 0;
  if (supply_V < lo) code = cause::kVoltageLow;
  else if (supply_V > hi) code = cause::kVoltageHigh;
  if (code != 0 && code == voltage_cause) voltage_out_ns += dt_ns;
  else voltage_out_ns = 0;
  voltage_cause = code;
  const bool out = code != 0 && voltage_out_ns >= kVoltageDebounce_ns;
  if (out && motor_on()) {
    raise_error(ErrorBit::MotorVoltage, code);
  }
  set_warning(WarningBit::MotorVoltage, out && !motor_on() ? code : 0);

  // Locator stops by itself after 10 minutes (manual 6.6, 127).
  if (locator && time_ns - locator_start_ns >= kLocatorDuration_ns) locator = false;
}

void Device::Impl::run_diagnostics(int64_t dt_ns) {
  auto count_minutes = [&](int64_t& rem, uint16_t index, uint8_t sub) {
    rem += dt_ns;
    while (rem >= kMinute_ns) {
      rem -= kMinute_ns;
      store.set_raw_internal(index, sub, store.raw(index, sub) + 1);
    }
  };
  count_minutes(powered_rem_ns, 97, 1);
  if (motor_on()) count_minutes(motor_on_rem_ns, 97, 2);
  if (state == State::Busy) count_minutes(moving_rem_ns, 97, 3);
  if (faults.warning(WarningBit::Temperature) != 0) count_minutes(temp_warn_rem_ns, 100, 0);
  // Maximum temperatures (98 ever, 99 resettable), raw 0.5 C.
  const int64_t t_raw = std::clamp<int64_t>(std::llround(temperature_C * 2.0), 0, 255);
  for (uint16_t index : {uint16_t{98}, uint16_t{99}}) {
    if (t_raw > store.raw(index, 2)) {
      store.set_raw_internal(index, 2, t_raw);
      store.set_raw_internal(index, 1, store.raw(97, 1));
    }
  }
}

double Device::Impl::tracking_limit_deg() const {
  return static_cast<double>(store.raw(87, 1)) * kTrackingErrorRawUnit_deg; // A-PARAM: 87.1 raw unit
}

// Manual 3.1 (LED band), 6.2 index 83, 6.6 locator, 9 boot mode (A-LED-1 for blink timing).
LedColor Device::Impl::led() const {
  if (!powered) return LedColor::Off;
  if (boot_mode) return LedColor::Violet;
  if (locator) return (time_ns % kNsPerS) < kNsPerS / 2 ? LedColor::White : LedColor::Off;
  const int64_t mode = store.raw(83, 0);
  const bool err = faults.any_error();
  const bool warn = faults.any_warning();
  if (mode == 0) return LedColor::Off;
  if (mode == 2) return err ? LedColor::Red : warn ? LedColor::Orange : LedColor::Off;
  switch (state) {
    case State::ErrorOn:
    case State::ErrorOff:
      return LedColor::Red; // warnings are not shown in the error states
    case State::MotorOff:
      return warn ? LedColor::Orange : LedColor::Off;
    default:
      break;
  }
  if (warn && (time_ns % kNsPerS) < 200'000'000) return LedColor::Orange; // once per second for 200 ms
  return state == State::Ready ? LedColor::Green : state == State::Busy ? LedColor::Yellow : LedColor::Blue;
}

} // namespace sreh
