// Monitors and indicators of the Device: the link watchdog (manual 5),
// temperature and motor voltage (7.2, 7.3, index 85), the tracking error
// (index 87), the locator timeout (6.6), persistent diagnostics (6.3) and
// the LED band (3.1, index 83): how the Device acts on its monitors'
// verdicts (the monitors themselves: device_monitors.hpp).
#include <algorithm>
#include <cmath>

#include "device_logic/device_impl.hpp"

namespace sreh {

// Manual 5: the link is interrupted.
void Device::Impl::link_lost() {
  st.outputs_valid = false;
  config.store.abort_block(); // an open block download is discarded (iolink.md)
  if (!st.boot_mode && motor_on()) raise_error(ErrorBit::InvalidCommand, cause::kConnectionInterrupted);
}

void Device::Impl::run_monitors(int64_t dt_ns) {
  // Temperature (manual 7.2 114.3, 7.3 115.1).
  const auto heat = TemperatureMonitor::step(st.temperature_C, st.faults.warning(WarningBit::Temperature) != 0);
  if (heat.over_temperature && st.faults.error(ErrorBit::Temperature) == 0) {
    raise_error(ErrorBit::Temperature, cause::kOverTemperature);
  }
  st.faults.set_warning(WarningBit::Temperature, heat.warning ? cause::kTemperatureWarning : 0);

  // Motor voltage (manual 6.2 index 85, 7.2 114.4, 7.3 115.2): an error with
  // the motor on, a warning with it off.
  static const double min_scale = parameter_row(param::kMotorVoltageMin).display_scale; // mV -> V
  static const double max_scale = parameter_row(param::kMotorVoltageMax).display_scale;
  const double lo = static_cast<double>(config.store.raw(param::kMotorVoltageMin)) * min_scale;
  const double hi = static_cast<double>(config.store.raw(param::kMotorVoltageMax)) * max_scale;
  const uint8_t out = mon.voltage.step(st.supply_V, lo, hi, dt_ns);
  if (out != 0 && motor_on()) raise_error(ErrorBit::MotorVoltage, out);
  st.faults.set_warning(WarningBit::MotorVoltage, out != 0 && !motor_on() ? out : 0);

  mon.locator.step(st.time_ns); // manual 6.6, 127: stops by itself after 10 minutes
}

// Manual 6.3: operating times (97, 100) and maximum temperatures (98, 99).
void run_diagnostics(DiagnosticsClock& clock, ParameterStore& store, const DeviceState& st, int64_t dt_ns) {
  const auto minutes = clock.step(dt_ns, motor_is_on(st.state), st.state == State::Busy,
                                  st.faults.warning(WarningBit::Temperature) != 0);
  auto add = [&store](ParamId id, int64_t n) {
    if (n > 0) store.set_raw_internal(id, store.raw(id) + n);
  };
  add(param::kTotalOperatingTime, minutes.powered);
  add(param::kOperatingTimeMotorOn, minutes.motor_on);
  add(param::kOperatingTimeMoving, minutes.moving);
  add(param::kTimeWithTemperatureWarning, minutes.temp_warning);
  // Maximum temperatures (98 ever, 99 resettable), raw 0.5 C.
  const int64_t t_raw = std::clamp<int64_t>(std::llround(st.temperature_C * 2.0), 0, 255);
  for (const param::MaxTemperature& max : {param::kMaxTemperatureEver, param::kMaxTemperatureResettable}) {
    if (t_raw > store.raw(max.temperature)) {
      store.set_raw_internal(max.temperature, t_raw);
      store.set_raw_internal(max.operating_time, store.raw(param::kTotalOperatingTime));
    }
  }
}

double tracking_limit_deg(const ParameterStore& store) {
  return static_cast<double>(store.raw(param::kTrackingErrorMax)) * kTrackingErrorRawUnit_deg; // A-PARAM-1
}

// Manual 3.1 (LED band), 6.2 index 83, 6.6 locator, 9 boot mode (A-LED-1 for blink timing).
LedColor led_color(const DeviceState& st, const Locator& locator, const ParameterStore& store) {
  if (!st.powered) return LedColor::Off;
  if (st.boot_mode) return LedColor::Violet;
  if (locator.active) return (st.time_ns % kNsPerS) < kNsPerS / 2 ? LedColor::White : LedColor::Off;
  const int64_t mode = store.raw(param::kLedBandMode);
  const bool err = st.faults.any_error();
  const bool warn = st.faults.any_warning();
  if (mode == 0) return LedColor::Off;
  if (mode == 2) return err ? LedColor::Red : warn ? LedColor::Orange : LedColor::Off;
  switch (st.state) {
    case State::ErrorOn:
    case State::ErrorOff:
      return LedColor::Red; // warnings are not shown in the error states
    case State::MotorOff:
      return warn ? LedColor::Orange : LedColor::Off;
    default:
      break;
  }
  if (warn && (st.time_ns % kNsPerS) < 200'000'000) return LedColor::Orange; // once per second for 200 ms
  return st.state == State::Ready ? LedColor::Green : st.state == State::Busy ? LedColor::Yellow : LedColor::Blue;
}

} // namespace sreh
