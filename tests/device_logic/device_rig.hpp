// A test rig that drives the Device only as a master and a plant would:
// process data every 2 ms IO-Link cycle, ISDU requests, sensor readings every
// 0.1 ms control step. The plant is an ideal rigid inertia with Coulomb
// friction and the motor's torque-speed limit (no MuJoCo in device tests).
#pragma once
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "device_logic/device.hpp"
#include "device_logic/motor_model.hpp"
#include "device_logic/parameter_table.hpp"
#include "device_logic/units.hpp"
#include "twin/module_model.hpp"

namespace sreh::test {

// The module's drive as its model card gives it (models/sreh50-model.yaml).
inline const DriveModel& card_drive() { return default_module_model().drive; }

inline constexpr double kDt = 1e-4;
inline constexpr int kStepsPerCycle = 20; // 2 ms IO-Link cycle

inline State state_of(const ProcessDataIn& in) {
  if (in.error) return in.motor_off ? State::ErrorOff : State::ErrorOn;
  if (in.ready) return State::Ready;
  if (in.busy) return State::Busy;
  if (in.done) return State::Done;
  return State::MotorOff;
}

struct Rig {
  Device dev{card_drive()};
  ProcessDataOut pd{};
  ProcessDataIn in{};
  double angle_rad = 0;
  double vel_rad_s = 0;
  double load_kgm2 = 0; // actual load on the flange
  double friction_Nm = 0.004;
  double supply_V = 24.0;
  double temperature_C = 25.0;
  double external_Nm = 0;
  bool link_up = true;
  bool outputs_valid = true;
  bool answered = false; // did the last exchange get an answer
  MotorModel motor = card_drive().motor;

  SensorReadings sensors() const {
    return {static_cast<int64_t>(std::llround(angle_rad * kInternalCountsPerRev / (2 * kPi))), supply_V, temperature_C};
  }

  MotorCommand step() {
    const MotorCommand cmd = dev.tick(kDt, sensors());
    double t = external_Nm + (cmd.enabled ? motor.saturate(cmd.torque_Nm, vel_rad_s, supply_V) : 0.0);
    if (std::abs(vel_rad_s) > 1e-9) {
      t -= std::copysign(friction_Nm, vel_rad_s);
    } else if (std::abs(t) <= friction_Nm) {
      t = 0;
    } else {
      t -= std::copysign(friction_Nm, t);
    }
    const double j = kInternalInertia_kgm2 + load_kgm2;
    const double v_next = vel_rad_s + t / j * kDt;
    // Friction cannot reverse the motion within a step.
    vel_rad_s = (external_Nm == 0 && !cmd.enabled && v_next * vel_rad_s < 0) ? 0.0 : v_next;
    angle_rad += vel_rad_s * kDt;
    return cmd;
  }

  void cycle() {
    if (link_up) {
      const auto r = dev.exchange(encode(pd), outputs_valid);
      answered = r.has_value();
      if (r) in = decode_in(*r);
    }
    for (int i = 0; i < kStepsPerCycle; ++i) step();
  }

  void run_s(double seconds) {
    const auto n = static_cast<int>(std::llround(seconds / (kDt * kStepsPerCycle)));
    for (int i = 0; i < n; ++i) cycle();
  }

  // Runs cycles until pred() holds (true) or the time is up (false).
  bool run_until(const std::function<bool()>& pred, double max_s) {
    const auto n = static_cast<int>(std::llround(max_s / (kDt * kStepsPerCycle)));
    for (int i = 0; i < n; ++i) {
      cycle();
      if (pred()) return true;
    }
    return false;
  }
  bool wait_state(State s, double max_s = 1.0) {
    return run_until([&] { return state_of(in) == s; }, max_s);
  }

  State state() const { return state_of(in); }
  double position_deg() const { return wire_counts_to_deg(in.position_raw); }

  // Motor on and wait for Ready.
  void switch_on() {
    pd.motor_on = true;
    cycle();
    cycle();
  }
  // Sets target, parameter set and Move (the mode bits as they are); the
  // device sees them at the next cycle.
  void start_move(double deg, uint8_t set = 1) {
    pd.target_raw = static_cast<int32_t>(deg_to_wire_counts(deg));
    pd.parameter_set = set;
    pd.move = true;
  }
  // Absolute (or moded) move with parameter set 1; returns once Done or an error.
  bool move_to_deg(double deg, uint8_t set = 1, double max_s = 3.0) {
    start_move(deg, set);
    const bool ok = run_until([&] { return state() == State::Done || in.error; }, max_s);
    return ok && state() == State::Done;
  }
  // Set Origin pulse (manual 3.2 T6, T7): Done, then Ready again.
  void set_origin_pulse() {
    pd.set_origin = true;
    cycle();
    pd.set_origin = false;
    cycle();
  }
  void release_move() {
    pd.move = false;
    cycle();
  }

  IsduResult write_u(uint16_t index, uint8_t sub, int64_t value) {
    const ParameterEntry* e = find_parameter(index, sub);
    const ParamType type = e ? e->type : ParamType::UInt8;
    const auto bytes = encode_number(type, value);
    return dev.isdu_write(index, sub, bytes);
  }
  int64_t read_u(uint16_t index, uint8_t sub) {
    const IsduResult r = dev.isdu_read(index, sub);
    int64_t v = 0;
    for (uint8_t b : r.data) v = (v << 8) | b;
    return v;
  }
  IsduResult command(uint8_t cmd) {
    const std::vector<uint8_t> b{cmd};
    return dev.isdu_write(2, 0, b);
  }
  void power_cycle() {
    dev.power_off();
    dev.power_on(sensors());
    in = {};
  }
};

} // namespace sreh::test
