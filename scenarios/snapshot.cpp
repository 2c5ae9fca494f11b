#include "scenarios/snapshot.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "device_logic/fault_names.hpp"
#include "device_logic/units.hpp"

namespace sreh {

State state_from_status_bits(const ProcessDataIn& in, State fallback) {
  // Manual 3.1 table: Error with Motor Off is Error (Off), without it Error (On).
  if (in.error) return in.motor_off ? State::ErrorOff : State::ErrorOn;
  if (in.motor_off) return State::MotorOff;
  if (in.ready) return State::Ready;
  if (in.busy) return State::Busy;
  if (in.done) return State::Done;
  return fallback;
}

Snapshot take_snapshot(const Twin& twin) {
  Snapshot s;
  s.t_s = twin.time_s();
  s.in = twin.pd_in();
  s.telemetry = twin.telemetry();
  s.state = state_from_status_bits(s.in, s.telemetry.state);
  s.position_deg = wire_counts_to_deg(s.in.position_raw);
  s.iolink_led = twin.iolink_led();
  return s;
}

namespace {

class Evaluator {
 public:
  explicit Evaluator(const Variables& vars) : vars_(vars) {}
  void number(const char* name, const std::optional<Comparison>& want, double actual, int decimals) {
    if (!want) return;
    std::string why;
    const bool ok = want->holds(actual, vars_, &why);
    add(name, want->str(), fmt::format("{:.{}f}", actual, decimals) + (why.empty() ? "" : " (" + why + ")"), ok);
  }
  // A code byte (manual 2.4): the number, and the bits' names (issue 39).
  void code(const char* name, const std::optional<Comparison>& want, uint8_t actual, std::string (*names)(uint8_t)) {
    if (!want) return;
    std::string why;
    const bool ok = want->holds(actual, vars_, &why);
    const std::string named = actual == 0 ? "" : " (" + names(actual) + ")";
    add(name, want->str(), fmt::format("{}{}", actual, named) + (why.empty() ? "" : " (" + why + ")"), ok);
  }
  void flag(const char* name, const std::optional<bool>& want, bool actual) {
    if (!want) return;
    add(name, *want ? "1" : "0", actual ? "1" : "0", *want == actual);
  }
  template <typename T, typename NameOf>
  void one_of(const char* name, const std::vector<T>& want, T actual, NameOf name_of) {
    if (want.empty()) return;
    std::string w;
    for (T x : want) {
      if (!w.empty()) w += '|';
      w += name_of(x);
    }
    add(name, w, std::string(name_of(actual)), std::find(want.begin(), want.end(), actual) != want.end());
  }
  Evaluation result() { return std::move(e_); }

 private:
  void add(const char* name, const std::string& want, const std::string& actual, bool ok) {
    auto append = [](std::string& to, const std::string& what) {
      if (!to.empty()) to += ", ";
      to += what;
    };
    append(e_.expected, fmt::format("{} {}", name, want));
    append(e_.actual, fmt::format("{} {}", name, actual));
    if (!ok) {
      e_.passed = false;
      append(e_.mismatch, fmt::format("{} {} (want {})", name, actual, want));
    }
  }
  const Variables& vars_;
  Evaluation e_;
};

} // namespace

Evaluation evaluate(const Conditions& c, const Snapshot& s, const Variables& vars) {
  Evaluator ev(vars);
  ev.one_of("state", c.state, s.state, state_name);
  ev.number("position_deg", c.position_deg, s.position_deg, 4);
  ev.number("position_raw", c.position_raw, static_cast<double>(s.in.position_raw), 0);
  ev.code("error_code", c.error_code, s.in.error_code, error_byte_names);
  ev.code("warning_code", c.warning_code, s.in.warning_code, warning_byte_names);
  ev.flag("error", c.error, s.in.error);
  ev.flag("warning", c.warning, s.in.warning);
  ev.one_of("led", c.led, s.telemetry.led, led_name);
  ev.one_of("iolink_led", c.iolink_led, s.iolink_led, iolink_led_name);
  ev.number("temperature_C", c.temperature_C, s.telemetry.temperature_C, 2);
  ev.number("supply_V", c.supply_V, s.telemetry.supply_V, 3);
  ev.number("velocity_dps", c.velocity_dps, s.telemetry.velocity_dps, 2);
  ev.number("tracking_error_deg", c.tracking_error_deg, s.telemetry.tracking_error_deg, 4);
  return ev.result();
}

std::optional<double> quantity(std::string_view key, const Snapshot& s) {
  if (key == "position_deg") return s.position_deg;
  if (key == "position_raw") return static_cast<double>(s.in.position_raw);
  if (key == "error_code") return s.in.error_code;
  if (key == "warning_code") return s.in.warning_code;
  if (key == "temperature_C") return s.telemetry.temperature_C;
  if (key == "supply_V") return s.telemetry.supply_V;
  if (key == "velocity_dps") return s.telemetry.velocity_dps;
  if (key == "tracking_error_deg") return s.telemetry.tracking_error_deg;
  return std::nullopt;
}

} // namespace sreh
