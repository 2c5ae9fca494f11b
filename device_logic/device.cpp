// The SREH-50-IOL firmware: power-on, process data, state machine, the
// control step's order (manual chapters 3, 5, 7). Motion and move records
// are in device_motion.cpp, monitors in device_monitors.cpp, ISDU routing in
// device_isdu.cpp, the public face in device_api.cpp.
#include <algorithm>
#include <utility>

#include "device_logic/device_impl.hpp"
#include "device_logic/position_frame.hpp"

namespace sreh {

int64_t Device::Impl::user_now() const { return user_position(st.encoder, config.dir(), st.origin); }

// Manual 4.3.3: on power-up, on writing index 86, on command 170.
void Device::Impl::init_origin() {
  st.origin = initial_origin(st.encoder, config.dir(), config.store.raw(param::kPositionZero));
}

// Everything volatile starts afresh; the configuration is kept.
void Device::Impl::power_on(const SensorReadings& s) {
  MoveRecorder records = std::move(st.move_recorder); // records not yet handed out survive
  st = DeviceState();
  mon = DeviceMonitors();
  st.controller = PositionController(config.drive.gains);
  st.move_recorder = std::move(records);
  st.move_recorder.restart_numbering();
  st.powered = true;
  st.encoder = s.encoder_counts;
  st.prev_encoder = st.encoder;
  st.supply_V = s.supply_V;
  st.temperature_C = s.temperature_C;
  init_origin();
  st.hold_phys = st.encoder;
  st.boot_mode = config.firmware_failed; // manual 9: only boot mode until a good image
  mon.link.link_up = true; // Startup until the master moves on, or off once the watchdog expires (A-LINK-3)
}

// ---------------------------------------------------------------------------
// Process data out: derive the events of this cycle from the edges (manual 3.2)

void Device::Impl::process_outputs(const ProcessDataOut& next) {
  const ProcessDataOut prev = st.pd;
  st.pd = next;
  auto rose = [](bool before, bool now) { return !before && now; };

  if (!next.motor_on && motor_on()) apply(Event::SwitchOff); // T2, T9, or 114.6/1 in Busy/Done
  // A-SM-6: while holding, a new selection retunes the loop for that set's load.
  if (motor_on() && st.phase == MotionPhase::Hold && next.parameter_set != prev.parameter_set) {
    tune_for_set(st, config.store, next.parameter_set);
  }

  // T10.1 / T10.2; with the motor off only if Motor On = 0 (manual 3.3).
  if (rose(prev.reset_error, next.reset_error)) {
    if (st.state == State::ErrorOn || (st.state == State::ErrorOff && !next.motor_on)) apply(Event::ResetError);
  }

  const bool move_rose = rose(prev.move, next.move);
  const bool origin_rose = rose(prev.set_origin, next.set_origin);
  if ((move_rose || origin_rose) && next.move && next.set_origin) {
    raise_error(ErrorBit::InvalidCommand, cause::kMoveAndSetOrigin); // 114.6/6
  } else if (move_rose) {
    if (st.state == State::Ready) {
      uint8_t code = 0;
      if (auto bad = prepare_move(next, code)) {
        raise_error(*bad, code); // 114.7: refused before any motion
      } else {
        apply(next.stop ? Event::MoveStartStopped : Event::MoveStart);
      }
    } else {
      apply(next.stop ? Event::MoveStartStopped : Event::MoveStart); // the table raises 114.6/4
    }
  } else if (origin_rose) {
    apply(Event::SetOrigin);
  }

  if (!move_rose && prev.move && !next.move) apply(Event::MoveReleased);
  if (!origin_rose && prev.set_origin && !next.set_origin) apply(Event::SetOriginReleased);
  if (rose(prev.stop, next.stop) && st.state == State::Busy && st.phase == MotionPhase::Travel) {
    apply(Event::StopMove);
  }

  // T1: Motor On is a level; the other command bits must be 0 (A-SM-1).
  if (next.motor_on && st.state == State::MotorOff && !next.move && !next.reset_error && !next.set_origin) {
    apply(Event::SwitchOn);
  }
}

// Manual 3.4 / 7.2 114.7: validate the latched command and compute its target.
std::optional<ErrorBit> Device::Impl::prepare_move(const ProcessDataOut& cmd, uint8_t& code) {
  if (cmd.parameter_set > 7) {
    code = cause::kInvalidParameterSet;
    return ErrorBit::InvalidParameter;
  }
  if (cmd.relative && cmd.shortest_path) {
    code = cause::kRelativeAndShortestPath;
    return ErrorBit::InvalidParameter;
  }
  const int64_t actual = user_now();
  int64_t target_user = 0;
  if (cmd.shortest_path) {
    target_user = shortest_path_target(actual, cmd.target_raw);
  } else if (cmd.relative) {
    // From the last target, except on the first move after switching on or
    // after a positioning error: then from the actual position.
    const int64_t from = st.last_target_phys ? user_position(*st.last_target_phys, config.dir(), st.origin) : actual;
    target_user = from + int64_t{cmd.target_raw} * kInternalPerWireCount;
  } else {
    target_user = int64_t{cmd.target_raw} * kInternalPerWireCount;
  }
  // Manual 6.2 index 81: refused whatever the mode, before any motion.
  if (config.store.raw(param::kPositionLimitActive) == 1) {
    const int64_t lo = config.store.raw(param::kPositionLimitMin) * kInternalPerWireCount;
    const int64_t hi = config.store.raw(param::kPositionLimitMax) * kInternalPerWireCount;
    if (target_user < lo || target_user > hi) {
      code = cause::kInvalidTarget;
      return ErrorBit::InvalidParameter;
    }
  }
  st.latched = cmd;
  st.pending_target_phys = physical_position(target_user, config.dir(), st.origin);
  return std::nullopt;
}

void Device::Impl::apply(Event e) {
  const Transition* t = find_transition(st.state, e);
  if (t == nullptr) return; // no effect in this state
  if (t->raises) {
    raise_error(*t->raises, t->cause);
    return;
  }
  enter(t->to, e);
}

// Manual 3.3, 2.4: sticky cause per bit; T8.1 keeps the motor on where the
// error allows it, T8.2 switches it off.
void Device::Impl::raise_error(ErrorBit bit, uint8_t code) {
  auto& slot = st.faults.error_cause[static_cast<int>(bit)];
  if (slot == 0) ++st.error_counter;
  slot = code;
  if (bit == ErrorBit::Positioning) st.last_target_phys.reset(); // manual 3.4: next relative move from actual
  apply(error_switches_motor_off(bit, code) ? Event::ErrorMotorOff : Event::ErrorKeepsMotor);
}

void Device::Impl::enter(State to, Event via) {
  const bool was_on = motor_on();
  const State from = st.state;
  st.state = to;
  const bool now_on = motor_on();

  if (!was_on && now_on) { // T1: hold where the flange is
    st.hold_phys = st.encoder;
    st.setpoint = KinematicState{internal_counts_to_rad(st.encoder), 0, 0, 0};
    st.controller.reset(internal_counts_to_rad(st.encoder));
    // A-SM-6: the set the PLC has selected now (set 0 for an invalid number).
    tune_for_set(st, config.store, st.pd.parameter_set < param::kMotionSets ? st.pd.parameter_set : uint8_t{0});
    st.last_target_phys.reset(); // manual 3.4: first relative move from the actual position
    st.phase = MotionPhase::Hold;
  }
  if (was_on && !now_on) { // T2, T9, T8.2
    st.phase = MotionPhase::Hold;
    st.positioned = false;
    st.faults.set_warning(WarningBit::Positioning, 0); // manual 3.5.7
    st.torque_Nm = 0;
  }

  switch (via) {
    case Event::MoveStart: // T3: parameters latched now
      start_move();
      break;
    case Event::MoveStartStopped: // T3 with Stop: Done without moving
      st.positioned = false;
      st.faults.set_warning(WarningBit::Positioning, 0);
      break;
    case Event::StopMove: // T4
      start_stop_profile(st);
      st.move_recorder.mark_stopped();
      break;
    case Event::MotionComplete: // T5
      st.last_target_phys = st.target_phys;
      st.positioned = true;
      break;
    case Event::SetOrigin: // T6, manual 4.3.2: position jumps to 0, flange does not turn
      st.origin += user_now();
      break;
    case Event::ErrorKeepsMotor: // T8.1: an aborted move brakes and holds
      if (from == State::Busy && st.phase == MotionPhase::Travel) start_stop_profile(st);
      else if (st.phase == MotionPhase::Settle) st.phase = MotionPhase::Hold;
      break;
    case Event::ResetError:
      st.faults.error_cause = {};
      break;
    default:
      break;
  }
}

// Manual 2.3: what the module reports, from its state and its position in
// the process-data frame (user_counts: Impl::user_now()).
ProcessDataIn pd_in(const DeviceState& st, int64_t user_counts) {
  ProcessDataIn in;
  in.position_raw = wrap_wire_position(user_to_wire(user_counts));
  if (st.boot_mode) {
    in.motor_off = true;
    return in;
  }
  in.error_code = st.faults.error_byte();
  in.warning_code = st.faults.warning_byte();
  in.error = in.error_code != 0;
  in.warning = in.warning_code != 0;
  in.motor_off = !motor_is_on(st.state);
  in.ready = st.state == State::Ready;
  in.busy = st.state == State::Busy;
  in.done = st.state == State::Done;
  return in;
}

// One control step of dt_ns: the device's clocks are integer nanoseconds
// (docs/style.md 8); a step length in seconds is derived, never summed.
MotorCommand Device::Impl::tick(int64_t dt_ns, const SensorReadings& sensors) {
  if (!st.powered) return {};
  st.time_ns += dt_ns;
  st.encoder = sensors.encoder_counts;
  st.supply_V = sensors.supply_V;
  st.temperature_C = sensors.temperature_C;
  const double dt_s = ns_to_seconds(dt_ns);
  if (dt_ns > 0) { // encoder speed, first-order filtered (A-MON-3)
    const double raw = internal_counts_to_rad(st.encoder - st.prev_encoder) / dt_s;
    st.velocity_rad_s += (raw - st.velocity_rad_s) * std::min(1.0, dt_s / config.drive.speed_filter_s);
  }
  st.prev_encoder = st.encoder;

  if (mon.link.step(dt_ns)) link_lost(); // communication watchdog (manual 5, A-LINK-1)
  run_diagnostics(mon.diagnostics, config.store, st, dt_ns);
  if (st.boot_mode) return {};
  run_monitors(dt_ns);
  const MotorCommand cmd = control(dt_ns, dt_s);
  record_move_step();
  return cmd;
}

} // namespace sreh
