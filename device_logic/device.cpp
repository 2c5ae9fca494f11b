// The SREH-50-IOL firmware: process data, state machine, motion, monitors.
// Manual chapters 3, 4, 5, 7. ISDU routing is in device_isdu.cpp.
#include "device_logic/device.hpp"

#include <algorithm>
#include <cmath>

#include "device_logic/device_impl.hpp"

#include <utility>
#include "device_logic/position_frame.hpp"

namespace sreh {

namespace {
double counts_to_rad(int64_t c) { return internal_counts_to_rad(c); }
} // namespace

Device::Impl::Impl() = default;
Device::Impl::Impl(ParameterStore s) : store(std::move(s)) {}

int64_t Device::Impl::user_now() const { return user_position(encoder, dir(), origin); }

// Manual 4.3.3: on power-up, on writing index 86, on command 170.
void Device::Impl::init_origin() { origin = initial_origin(encoder, dir(), store.raw(86, 0)); }

void Device::Impl::power_on(const SensorReadings& s) {
  const ParameterStore keep = std::move(store);
  const bool failed = firmware_failed;
  MoveRecorder records = std::move(move_recorder); // records not yet handed out survive
  *this = Impl(keep);
  firmware_failed = failed;
  move_recorder = std::move(records);
  move_recorder.restart_numbering();
  powered = true;
  encoder = s.encoder_counts;
  prev_encoder = encoder;
  supply_V = s.supply_V;
  temperature_C = s.temperature_C;
  init_origin();
  hold_phys = encoder;
  boot_mode = firmware_failed; // manual 9: only boot mode until a good image
  link_up = true; // Startup until the master moves on, or off once the watchdog expires (A-LINK-3)
}

// ---------------------------------------------------------------------------
// Process data out: derive the events of this cycle from the edges (manual 3.2)

void Device::Impl::process_outputs(const ProcessDataOut& next) {
  const ProcessDataOut prev = pd;
  pd = next;
  auto rose = [](bool before, bool now) { return !before && now; };

  if (!next.motor_on && motor_on()) apply(Event::SwitchOff); // T2, T9, or 114.6/1 in Busy/Done

  // T10.1 / T10.2; with the motor off only if Motor On = 0 (manual 3.3).
  if (rose(prev.reset_error, next.reset_error)) {
    if (state == State::ErrorOn || (state == State::ErrorOff && !next.motor_on)) apply(Event::ResetError);
  }

  const bool move_rose = rose(prev.move, next.move);
  const bool origin_rose = rose(prev.set_origin, next.set_origin);
  if ((move_rose || origin_rose) && next.move && next.set_origin) {
    raise_error(ErrorBit::InvalidCommand, cause::kMoveAndSetOrigin); // 114.6/6
  } else if (move_rose) {
    if (state == State::Ready) {
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
  if (rose(prev.stop, next.stop) && state == State::Busy && phase == MotionPhase::Travel) apply(Event::StopMove);

  // T1: Motor On is a level; the other command bits must be 0 (A-SM-1).
  if (next.motor_on && state == State::MotorOff && !next.move && !next.reset_error && !next.set_origin) {
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
    target_user = shortest_path_target(actual, cmd.target_position);
  } else if (cmd.relative) {
    // From the last target, except on the first move after switching on or
    // after a positioning error: then from the actual position.
    const int64_t from = last_target_phys ? user_position(*last_target_phys, dir(), origin) : actual;
    target_user = from + int64_t{cmd.target_position} * kInternalPerWireCount;
  } else {
    target_user = int64_t{cmd.target_position} * kInternalPerWireCount;
  }
  // Manual 6.2 index 81: refused whatever the mode, before any motion.
  if (store.raw(81, 3) == 1) {
    const int64_t lo = store.raw(81, 1) * kInternalPerWireCount;
    const int64_t hi = store.raw(81, 2) * kInternalPerWireCount;
    if (target_user < lo || target_user > hi) {
      code = cause::kInvalidTarget;
      return ErrorBit::InvalidParameter;
    }
  }
  latched = cmd;
  pending_target_phys = physical_position(target_user, dir(), origin);
  return std::nullopt;
}

void Device::Impl::apply(Event e) {
  const Transition* t = find_transition(state, e);
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
  auto& slot = faults.error_cause[static_cast<int>(bit)];
  if (slot == 0) ++error_counter;
  slot = code;
  if (bit == ErrorBit::Positioning) last_target_phys.reset(); // manual 3.4: next relative move from actual
  apply(error_switches_motor_off(bit, code) ? Event::ErrorMotorOff : Event::ErrorKeepsMotor);
}

void Device::Impl::start_stop_profile() {
  KinematicState now = setpoint;
  now.pos = 0;
  profile = Profile::stop(now, limits);
  const double start_rad = setpoint.pos;
  profile_t_s = 0;
  // Stop profile positions are relative to where braking starts.
  target_phys = rad_to_internal_counts(start_rad + profile.end_position_rad());
  stop_base_rad = start_rad;
  phase = MotionPhase::Travel;
}

void Device::Impl::enter(State to, Event via) {
  const bool was_on = motor_on();
  const State from = state;
  state = to;
  const bool now_on = motor_on();

  if (!was_on && now_on) { // T1: hold where the flange is
    hold_phys = encoder;
    setpoint = KinematicState{counts_to_rad(encoder), 0, 0, 0};
    controller.reset(counts_to_rad(encoder));
    const MotionParameterSet set0 = store.motion_set(0);
    limits = limits_from_parameter_set(set0.speed_dps, set0.accel_pct, set0.jerk_pct, set0.load_gcm2);
    inertia_kgm2 = kInternalInertia_kgm2 + gcm2_to_kgm2(set0.load_gcm2);
    last_target_phys.reset(); // manual 3.4: first relative move from the actual position
    phase = MotionPhase::Hold;
  }
  if (was_on && !now_on) { // T2, T9, T8.2
    phase = MotionPhase::Hold;
    positioned = false;
    faults.warning_cause[static_cast<int>(WarningBit::Positioning)] = 0; // manual 3.5.7
    torque_Nm = 0;
  }

  switch (via) {
    case Event::MoveStart: { // T3: parameters latched now
      const MotionParameterSet set = store.motion_set(latched.parameter_set);
      limits = limits_from_parameter_set(set.speed_dps, set.accel_pct, set.jerk_pct, set.load_gcm2);
      inertia_kgm2 = kInternalInertia_kgm2 + gcm2_to_kgm2(set.load_gcm2);
      settle = SettlingParameters{deg_to_rad(set.tolerance_deg), set.wait_ms * 1e-3, set.settling_timeout_ms * 1e-3,
                                  set.timeout_enabled};
      start_phys = hold_phys;
      target_phys = pending_target_phys;
      stop_base_rad = counts_to_rad(start_phys);
      profile = Profile::rest_to_rest(counts_to_rad(target_phys - start_phys), limits);
      profile_t_s = 0;
      phase = MotionPhase::Travel;
      positioned = false;
      faults.warning_cause[static_cast<int>(WarningBit::Positioning)] = 0; // manual 3.5.7: next move clears
      store.set_raw_internal(96, 0, store.raw(96, 0) + 1); // manual 6.3 (DE): number of moves
      ++moves_started;
      move_recorder.start({time_ns, latched.parameter_set, user_deg(start_phys), user_deg(target_phys),
                           set.tolerance_deg, set.wait_ms, set.settling_timeout_ms, set.timeout_enabled});
      if (profile.duration_s() <= 0) { // a zero-length move is at (b) at once: travel 0
        move_recorder.step(time_ns, 0.0, internal_counts_to_deg(user_now()), false);
      }
      break;
    }
    case Event::MoveStartStopped: // T3 with Stop: Done without moving
      positioned = false;
      faults.warning_cause[static_cast<int>(WarningBit::Positioning)] = 0;
      break;
    case Event::StopMove: // T4
      start_stop_profile();
      move_recorder.mark_stopped();
      break;
    case Event::MotionComplete: // T5
      last_target_phys = target_phys;
      positioned = true;
      break;
    case Event::SetOrigin: // T6, manual 4.3.2: position jumps to 0, flange does not turn
      origin += user_now();
      break;
    case Event::ErrorKeepsMotor: // T8.1: an aborted move brakes and holds
      if (from == State::Busy && phase == MotionPhase::Travel) start_stop_profile();
      else if (phase == MotionPhase::Settle) phase = MotionPhase::Hold;
      break;
    case Event::ResetError:
      faults.error_cause = {};
      break;
    default:
      break;
  }
}

// ---------------------------------------------------------------------------
// Control step

MotorCommand Device::Impl::control(double dt_s) {
  const double measured = counts_to_rad(encoder);
  step_tracking_error_deg = 0;
  if (!motor_on()) { // no setpoint: the flange turns freely (manual 3.1 Motor Off)
    setpoint = KinematicState{measured, 0, 0, 0};
    torque_Nm = 0;
    return {};
  }
  switch (phase) {
    case MotionPhase::Travel: {
      profile_t_s += dt_s;
      const KinematicState s = profile.at(profile_t_s);
      setpoint = KinematicState{stop_base_rad + s.pos, s.vel, s.acc, s.jerk};
      if (profile_t_s >= profile.duration_s()) { // point (b) of Fig. 3
        hold_phys = target_phys;
        setpoint = KinematicState{counts_to_rad(hold_phys), 0, 0, 0};
        if (state == State::Busy) {
          phase = MotionPhase::Settle;
          settling.start(settle);
        } else {
          phase = MotionPhase::Hold;
        }
      }
      break;
    }
    case MotionPhase::Settle:
    case MotionPhase::Hold:
      setpoint = KinematicState{counts_to_rad(hold_phys), 0, 0, 0};
      break;
  }

  const double error_rad = setpoint.pos - measured;
  step_tracking_error_deg = std::abs(rad_to_deg(error_rad)); // before any trip below, so the trip is in the records
  // Tracking error (manual 6.2 index 87, 7.2 114.5): against the planned setpoint.
  if (store.raw(87, 2) == 1 && std::abs(rad_to_deg(error_rad)) > tracking_limit_deg()) {
    raise_error(ErrorBit::TrackingError, cause::kTrackingError);
    return {};
  }
  if (phase == MotionPhase::Settle) {
    switch (settling.update(counts_to_rad(hold_phys) - measured, dt_s)) {
      case SettlingResult::Done:
        phase = MotionPhase::Hold;
        apply(Event::MotionComplete); // T5, point (f)
        break;
      case SettlingResult::Timeout:
        phase = MotionPhase::Hold;
        raise_error(ErrorBit::Positioning, cause::kSettlingTimeout); // 114.8
        break;
      case SettlingResult::Settling:
        break;
    }
  }
  // Manual 3.5.7 / 7.3 115.3: the window left after positioning completed.
  if (positioned && std::abs(counts_to_rad(hold_phys) - measured) > settle.tolerance_rad) {
    set_warning(WarningBit::Positioning, cause::kLeftToleranceWindow);
  }
  if (!motor_on()) return {}; // an error above switched it off

  const double vel = velocity_rad_s;
  const double lim_pos = motor.max_torque_Nm(vel, supply_V, +1.0);
  const double lim_neg = motor.max_torque_Nm(vel, supply_V, -1.0);
  torque_Nm = controller.update(setpoint, measured, inertia_kgm2, lim_pos, lim_neg, dt_s);
  torque_limit_Nm = torque_Nm >= 0 ? lim_pos : lim_neg;
  return MotorCommand{torque_Nm, true};
}

double Device::Impl::user_deg(int64_t phys_counts) const {
  return internal_counts_to_deg(user_position(phys_counts, dir(), origin));
}

double Device::Impl::setpoint_user_deg() const {
  return motor_on() ? rad_to_deg(dir() * setpoint.pos) - internal_counts_to_deg(origin)
                    : internal_counts_to_deg(user_now());
}

// Move records (issue 13, manual 3.5.2 Fig. 3): every control step, on the
// encoder reading, with the set latched at T3. Done ends a record at (f);
// any other way out of Busy (an error, the motor off) ends it without a
// settling time. A completed move stays held while its target is.
void Device::Impl::record_move_step() {
  // The one tracking error (issue 16): setpoint minus encoder, every control step.
  peak_tracking_error_deg = std::max(peak_tracking_error_deg, step_tracking_error_deg);
  if (!move_recorder.open() && !move_recorder.holding()) return; // the common case: nothing more per step
  const double position = internal_counts_to_deg(user_now());
  if (move_recorder.open()) {
    move_recorder.step(time_ns, step_tracking_error_deg, position, state == State::Busy && phase == MotionPhase::Travel);
    if (state == State::Done) {
      move_recorder.finish(time_ns, MoveOutcome::Done, position);
    } else if (state != State::Busy) {
      move_recorder.finish(time_ns, faults.any_error() ? MoveOutcome::Error : MoveOutcome::MotorOff, position,
                           faults.error_byte());
    }
  } else if (state == State::Done || state == State::Ready || state == State::Busy) {
    move_recorder.step(time_ns, step_tracking_error_deg, position, false);
  } else {
    move_recorder.release();
  }
}

ProcessDataIn Device::Impl::pd_in() const {
  ProcessDataIn in;
  in.actual_position = wrap_wire_position(user_to_wire(user_now()));
  if (boot_mode) {
    in.motor_off = true;
    return in;
  }
  in.error_code = faults.error_byte();
  in.warning_code = faults.warning_byte();
  in.error = in.error_code != 0;
  in.warning = in.warning_code != 0;
  in.motor_off = !motor_on();
  in.ready = state == State::Ready;
  in.busy = state == State::Busy;
  in.done = state == State::Done;
  return in;
}

// ---------------------------------------------------------------------------
// Device: the public face

Device::Device() : impl_(std::make_unique<Impl>()) { impl_->power_on(SensorReadings{}); }

Device::Device(const std::vector<uint8_t>& nvm_image) : impl_(std::make_unique<Impl>()) {
  if (!restore_nvm(*impl_, nvm_image)) {
    // A corrupt memory image: factory configuration and error 114.1 code 1 (A-NVM-1).
    impl_->power_on(SensorReadings{});
    impl_->raise_error(ErrorBit::DeviceError, cause::kInternalConfiguration);
    return;
  }
  impl_->power_on(SensorReadings{});
}

Device::~Device() = default;
Device::Device(const Device& other) : impl_(std::make_unique<Impl>(*other.impl_)) {}
Device& Device::operator=(const Device& other) {
  if (this != &other) *impl_ = *other.impl_;
  return *this;
}

std::optional<PdInFrame> Device::exchange(const PdOutFrame& out, bool outputs_valid) {
  Impl& d = *impl_;
  if (!d.powered || d.comm_blocked) return std::nullopt;
  d.since_exchange_ns = 0;
  d.link_up = true;
  d.com_phase = ComPhase::Operate;
  if (!d.boot_mode) {
    if (outputs_valid) {
      d.last_out_frame = out;
      d.outputs_valid = true;
      d.process_outputs(decode_out(out));
    } else if (d.outputs_valid) {
      // Manual 5: valid -> invalid behaves like a connection interruption.
      d.outputs_valid = false;
      if (d.motor_on()) d.raise_error(ErrorBit::InvalidCommand, cause::kOutputsInvalid);
    }
  }
  d.last_in_frame = encode(d.pd_in());
  return d.last_in_frame;
}

MotorCommand Device::tick(double dt_s, const SensorReadings& sensors) {
  Impl& d = *impl_;
  if (!d.powered) return {};
  const int64_t dt_ns = seconds_to_ns(dt_s);
  d.time_ns += dt_ns;
  d.encoder = sensors.encoder_counts;
  d.supply_V = sensors.supply_V;
  d.temperature_C = sensors.temperature_C;
  if (dt_s > 0) { // encoder speed, first-order filtered (A-MON-3)
    const double raw = internal_counts_to_rad(d.encoder - d.prev_encoder) / dt_s;
    d.velocity_rad_s += (raw - d.velocity_rad_s) * std::min(1.0, dt_s / kVelocityFilter_s);
  }
  d.prev_encoder = d.encoder;

  // Communication watchdog (manual 5, A-LINK-1).
  d.since_exchange_ns += dt_ns;
  if (d.link_up && d.since_exchange_ns > d.watchdog_ns()) {
    d.link_up = false;
    d.outputs_valid = false;
    d.store.abort_block(); // an open block download is discarded (iolink.md)
    if (!d.boot_mode && d.motor_on()) d.raise_error(ErrorBit::InvalidCommand, cause::kConnectionInterrupted);
  }
  d.run_diagnostics(dt_ns);
  if (d.boot_mode) return {};
  d.run_monitors(dt_ns);
  const MotorCommand cmd = d.control(dt_s);
  d.record_move_step();
  return cmd;
}

IsduResult Device::isdu_read(uint16_t index, uint8_t subindex) { return impl_->read(index, subindex); }
IsduResult Device::isdu_write(uint16_t index, uint8_t subindex, std::span<const uint8_t> data) {
  return impl_->write(index, subindex, data);
}

void Device::power_off() {
  Impl& d = *impl_;
  d.store.abort_block();
  if (d.powered) { // a move in progress ends with the supply; a held one is handed out
    d.move_recorder.finish(d.time_ns, MoveOutcome::MotorOff, internal_counts_to_deg(d.user_now()));
    d.move_recorder.release();
  }
  d.powered = false;
}

double Device::take_peak_tracking_error_deg() { return std::exchange(impl_->peak_tracking_error_deg, 0.0); }

std::vector<MoveRecord> Device::take_finished_moves() { return impl_->move_recorder.take_finished(); }
std::optional<MoveRecord> Device::pending_move() const { return impl_->move_recorder.pending(); }
void Device::power_on(const SensorReadings& sensors) { impl_->power_on(sensors); }
bool Device::powered() const { return impl_->powered; }
bool Device::in_boot_mode() const { return impl_->boot_mode; }
LedColor Device::led() const { return impl_->led(); }
std::vector<uint8_t> Device::save_nvm() const { return save_nvm_image(*impl_); }

// Manual 1: Startup after every power-on until the master moves on;
// Operate also with the outputs marked invalid (DeviceOperate, manual 5:
// the device is in OPERATE then); off when the link is lost (A-LINK-3).
IoLinkLedMode Device::io_link_led() const {
  const Impl& d = *impl_;
  if (!d.powered || d.comm_blocked) return IoLinkLedMode::NotConnected;
  switch (d.com_phase) {
    case ComPhase::Startup: return d.link_up ? IoLinkLedMode::Startup : IoLinkLedMode::NotConnected;
    case ComPhase::Preoperate: return d.link_up ? IoLinkLedMode::Preoperate : IoLinkLedMode::NotConnected;
    case ComPhase::Operate: return d.link_up ? IoLinkLedMode::Operate : IoLinkLedMode::NotConnected;
  }
  return IoLinkLedMode::NotConnected;
}

bool Device::startup_cycle(ComPhase phase) {
  Impl& d = *impl_;
  if (!d.powered || d.comm_blocked) return false;
  d.since_exchange_ns = 0;
  d.link_up = true;
  d.com_phase = phase == ComPhase::Operate ? ComPhase::Preoperate : phase; // OPERATE is exchange()
  return true;
}

ComPhase Device::com_phase() const { return impl_->com_phase; }

void Device::set_master_cycle_time(double cycle_s) {
  impl_->master_cycle_ns = std::max<int64_t>(seconds_to_ns(cycle_s), 0);
}

// A-LINK-1: a link silent for longer than max(20 ms, 3 master cycles) is interrupted.
int64_t Device::Impl::watchdog_ns() const {
  return std::max(kLinkWatchdogMin_ns, kLinkWatchdogCycles * master_cycle_ns);
}

Telemetry Device::telemetry() const {
  const Impl& d = *impl_;
  Telemetry t;
  const int dir = d.dir();
  t.state = d.state;
  t.position_deg = internal_counts_to_deg(d.user_now());
  t.setpoint_deg = d.setpoint_user_deg();
  t.tracking_error_deg = t.setpoint_deg - t.position_deg;
  t.velocity_dps = rad_to_deg(dir * d.velocity_rad_s);
  t.torque_Nm = d.motor_on() ? d.torque_Nm : 0.0;
  t.torque_limit_Nm = d.torque_limit_Nm;
  t.supply_V = d.supply_V;
  t.temperature_C = d.temperature_C;
  t.error_code = d.faults.error_byte();
  t.warning_code = d.faults.warning_byte();
  t.led = d.led();
  t.moving = d.state == State::Busy && d.phase == MotionPhase::Travel;
  t.settling = d.phase == MotionPhase::Settle;
  t.moves_started = d.moves_started;
  t.tolerance_deg = rad_to_deg(d.settle.tolerance_rad);
  return t;
}

} // namespace sreh
