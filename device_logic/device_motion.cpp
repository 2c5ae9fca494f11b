// Motion of the Device (manual 3.4, 3.5, 3.2 T3/T4): the trajectory, the
// control step on the encoder reading, settling, and the move records.
#include <algorithm>
#include <cmath>

#include "device_logic/device_impl.hpp"
#include "device_logic/position_frame.hpp"

namespace sreh {

// A-SM-6: holding, the loop is tuned for the set selected in the process
// data (the set the PLC will move with; after a move, the latched one until
// the PLC selects another). An invalid number changes nothing (it raises
// 114.7.2 only with Move, manual 3.5).
void tune_for_set(DeviceState& st, const ParameterStore& store, uint8_t set_number) {
  if (set_number >= param::kMotionSets) return;
  st.hold_set = set_number;
  const MotionParameterSet set = store.motion_set(set_number);
  st.limits = limits_from_parameter_set(set.speed_dps, set.accel_pct, set.jerk_pct, set.load_gcm2);
  st.inertia_kgm2 = kInternalInertia_kgm2 + gcm2_to_kgm2(set.load_gcm2);
}

// T3: the set is latched now (manual 3.2); prepare_move() checked its number.
void Device::Impl::start_move() {
  tune_for_set(st, config.store, st.latched.parameter_set);
  const MotionParameterSet set = config.store.motion_set(st.latched.parameter_set);
  st.settle = SettlingParameters{deg_to_rad(set.tolerance_deg), set.wait_ms * 1e-3, set.settling_timeout_ms * 1e-3,
                                 set.timeout_enabled};
  st.start_phys = st.hold_phys;
  st.target_phys = st.pending_target_phys;
  st.stop_base_rad = internal_counts_to_rad(st.start_phys);
  st.profile = Profile::rest_to_rest(internal_counts_to_rad(st.target_phys - st.start_phys), st.limits);
  st.profile_ns = 0;
  st.phase = MotionPhase::Travel;
  st.positioned = false;
  st.faults.set_warning(WarningBit::Positioning, 0); // manual 3.5.7: next move clears
  // Manual 6.3 (DE): the number of moves.
  config.store.set_raw_internal(param::kMoveCount, config.store.raw(param::kMoveCount) + 1);
  ++st.moves_started;
  st.move_recorder.start({st.time_ns, st.latched.parameter_set, user_deg(st.start_phys), user_deg(st.target_phys),
                          set.tolerance_deg, set.wait_ms, set.settling_timeout_ms, set.timeout_enabled});
  if (st.profile.duration_s() <= 0) { // a zero-length move is at (b) at once: travel 0
    st.move_recorder.step(st.time_ns, 0.0, internal_counts_to_deg(user_now()), false);
  }
}

// T4 and T8.1: brake from the setpoint's state now (manual 3.2).
void start_stop_profile(DeviceState& st) {
  KinematicState now = st.setpoint;
  now.pos_rad = 0;
  st.profile = Profile::stop(now, st.limits);
  const double start_rad = st.setpoint.pos_rad;
  st.profile_ns = 0;
  // Stop profile positions are relative to where braking starts.
  st.target_phys = rad_to_internal_counts(start_rad + st.profile.end_position_rad());
  st.stop_base_rad = start_rad;
  st.phase = MotionPhase::Travel;
}

MotorCommand Device::Impl::control(int64_t dt_ns, double dt_s) {
  const double measured = internal_counts_to_rad(st.encoder);
  mon.tracking.idle();
  if (!motor_on()) { // no setpoint: the flange turns freely (manual 3.1 Motor Off)
    st.setpoint = KinematicState{measured, 0, 0, 0};
    st.torque_Nm = 0;
    return {};
  }
  switch (st.phase) {
    case MotionPhase::Travel: {
      // The planner is sampled at an integer time: no float sum drifts.
      st.profile_ns += dt_ns;
      const double t_s = ns_to_seconds(st.profile_ns);
      const KinematicState s = st.profile.at(t_s);
      st.setpoint = KinematicState{st.stop_base_rad + s.pos_rad, s.vel_rad_s, s.acc_rad_s2, s.jerk_rad_s3};
      if (t_s >= st.profile.duration_s()) { // point (b) of Fig. 3
        st.hold_phys = st.target_phys;
        st.setpoint = KinematicState{internal_counts_to_rad(st.hold_phys), 0, 0, 0};
        if (st.state == State::Busy) {
          st.phase = MotionPhase::Settle;
          st.settling.start(st.settle);
        } else {
          st.phase = MotionPhase::Hold;
        }
      }
      break;
    }
    case MotionPhase::Settle:
    case MotionPhase::Hold:
      st.setpoint = KinematicState{internal_counts_to_rad(st.hold_phys), 0, 0, 0};
      break;
  }

  // Tracking error (manual 6.2 index 87, 7.2 114.5): against the planned
  // setpoint, recorded before any trip so the trip is in the records.
  const double error_rad = st.setpoint.pos_rad - measured;
  if (mon.tracking.step(std::abs(rad_to_deg(error_rad)), tracking_limit_deg(config.store),
                        config.store.raw(param::kTrackingErrorActive) == 1)) {
    raise_error(ErrorBit::TrackingError, cause::kTrackingError);
    return {};
  }
  if (st.phase == MotionPhase::Settle) {
    switch (st.settling.update_ns(internal_counts_to_rad(st.hold_phys) - measured, dt_ns)) {
      case SettlingResult::Done:
        st.phase = MotionPhase::Hold;
        apply(Event::MotionComplete); // T5, point (f)
        break;
      case SettlingResult::Timeout:
        st.phase = MotionPhase::Hold;
        raise_error(ErrorBit::Positioning, cause::kSettlingTimeout); // 114.8
        break;
      case SettlingResult::Settling:
        break;
    }
  }
  // Manual 3.5.7 / 7.3 115.3: the window left after positioning completed.
  if (st.positioned && std::abs(internal_counts_to_rad(st.hold_phys) - measured) > st.settle.tolerance_rad) {
    st.faults.set_warning(WarningBit::Positioning, cause::kLeftToleranceWindow);
  }
  if (!motor_on()) return {}; // an error above switched it off

  const double vel = st.velocity_rad_s;
  const double lim_pos = config.drive.motor.max_torque_Nm(vel, st.supply_V, +1.0);
  const double lim_neg = config.drive.motor.max_torque_Nm(vel, st.supply_V, -1.0);
  st.torque_Nm = st.controller.update(st.setpoint, measured, st.inertia_kgm2, lim_pos, lim_neg, dt_s);
  st.torque_limit_Nm = st.torque_Nm >= 0 ? lim_pos : lim_neg;
  return MotorCommand{st.torque_Nm, true};
}

double Device::Impl::user_deg(int64_t phys_counts) const {
  return internal_counts_to_deg(user_position(phys_counts, config.dir(), st.origin));
}

double Device::Impl::setpoint_user_deg() const {
  return motor_on() ? rad_to_deg(config.dir() * st.setpoint.pos_rad) - internal_counts_to_deg(st.origin)
                    : internal_counts_to_deg(user_now());
}

// Move records (issue 13, manual 3.5.2 Fig. 3): every control step, on the
// encoder reading, with the set latched at T3. Done ends a record at (f);
// any other way out of Busy (an error, the motor off) ends it without a
// settling time. A completed move stays held while its target is.
void Device::Impl::record_move_step() {
  if (!st.move_recorder.open() && !st.move_recorder.holding()) return; // the common case: nothing more per step
  const double position = internal_counts_to_deg(user_now());
  const double error_deg = mon.tracking.step_error_deg;
  MoveRecorder& rec = st.move_recorder;
  if (rec.open()) {
    rec.step(st.time_ns, error_deg, position, st.state == State::Busy && st.phase == MotionPhase::Travel);
    if (st.state == State::Done) {
      rec.finish(st.time_ns, MoveOutcome::Done, position);
    } else if (st.state != State::Busy) {
      rec.finish(st.time_ns, st.faults.any_error() ? MoveOutcome::Error : MoveOutcome::MotorOff, position,
                 st.faults.error_byte());
    }
  } else if (st.state == State::Done || st.state == State::Ready || st.state == State::Busy) {
    rec.step(st.time_ns, error_deg, position, false);
  } else {
    rec.release();
  }
}

} // namespace sreh
