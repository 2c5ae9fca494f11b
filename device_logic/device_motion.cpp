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
void Device::Impl::tune_for_set(uint8_t set_number) {
  if (set_number >= param::kMotionSets) return;
  hold_set = set_number;
  const MotionParameterSet set = store.motion_set(set_number);
  limits = limits_from_parameter_set(set.speed_dps, set.accel_pct, set.jerk_pct, set.load_gcm2);
  inertia_kgm2 = kInternalInertia_kgm2 + gcm2_to_kgm2(set.load_gcm2);
}

// T3: the set is latched now (manual 3.2).
void Device::Impl::start_move() {
  hold_set = latched.parameter_set;
  const MotionParameterSet set = store.motion_set(latched.parameter_set);
  limits = limits_from_parameter_set(set.speed_dps, set.accel_pct, set.jerk_pct, set.load_gcm2);
  inertia_kgm2 = kInternalInertia_kgm2 + gcm2_to_kgm2(set.load_gcm2);
  settle = SettlingParameters{deg_to_rad(set.tolerance_deg), set.wait_ms * 1e-3, set.settling_timeout_ms * 1e-3,
                              set.timeout_enabled};
  start_phys = hold_phys;
  target_phys = pending_target_phys;
  stop_base_rad = internal_counts_to_rad(start_phys);
  profile = Profile::rest_to_rest(internal_counts_to_rad(target_phys - start_phys), limits);
  profile_ns = 0;
  phase = MotionPhase::Travel;
  positioned = false;
  faults.warning_cause[static_cast<int>(WarningBit::Positioning)] = 0; // manual 3.5.7: next move clears
  store.set_raw_internal(param::kMoveCount, store.raw(param::kMoveCount) + 1); // manual 6.3 (DE): number of moves
  ++moves_started;
  move_recorder.start({time_ns, latched.parameter_set, user_deg(start_phys), user_deg(target_phys),
                       set.tolerance_deg, set.wait_ms, set.settling_timeout_ms, set.timeout_enabled});
  if (profile.duration_s() <= 0) { // a zero-length move is at (b) at once: travel 0
    move_recorder.step(time_ns, 0.0, internal_counts_to_deg(user_now()), false);
  }
}

// T4 and T8.1: brake from the setpoint's state now (manual 3.2).
void Device::Impl::start_stop_profile() {
  KinematicState now = setpoint;
  now.pos_rad = 0;
  profile = Profile::stop(now, limits);
  const double start_rad = setpoint.pos_rad;
  profile_ns = 0;
  // Stop profile positions are relative to where braking starts.
  target_phys = rad_to_internal_counts(start_rad + profile.end_position_rad());
  stop_base_rad = start_rad;
  phase = MotionPhase::Travel;
}

MotorCommand Device::Impl::control(int64_t dt_ns, double dt_s) {
  const double measured = internal_counts_to_rad(encoder);
  tracking.idle();
  if (!motor_on()) { // no setpoint: the flange turns freely (manual 3.1 Motor Off)
    setpoint = KinematicState{measured, 0, 0, 0};
    torque_Nm = 0;
    return {};
  }
  switch (phase) {
    case MotionPhase::Travel: {
      // The planner is sampled at an integer time: no float sum drifts.
      profile_ns += dt_ns;
      const double t_s = ns_to_seconds(profile_ns);
      const KinematicState s = profile.at(t_s);
      setpoint = KinematicState{stop_base_rad + s.pos_rad, s.vel_rad_s, s.acc_rad_s2, s.jerk_rad_s3};
      if (t_s >= profile.duration_s()) { // point (b) of Fig. 3
        hold_phys = target_phys;
        setpoint = KinematicState{internal_counts_to_rad(hold_phys), 0, 0, 0};
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
      setpoint = KinematicState{internal_counts_to_rad(hold_phys), 0, 0, 0};
      break;
  }

  // Tracking error (manual 6.2 index 87, 7.2 114.5): against the planned
  // setpoint, recorded before any trip so the trip is in the records.
  const double error_rad = setpoint.pos_rad - measured;
  if (tracking.step(std::abs(rad_to_deg(error_rad)), tracking_limit_deg(),
                    store.raw(param::kTrackingErrorActive) == 1)) {
    raise_error(ErrorBit::TrackingError, cause::kTrackingError);
    return {};
  }
  if (phase == MotionPhase::Settle) {
    switch (settling.update_ns(internal_counts_to_rad(hold_phys) - measured, dt_ns)) {
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
  if (positioned && std::abs(internal_counts_to_rad(hold_phys) - measured) > settle.tolerance_rad) {
    set_warning(WarningBit::Positioning, cause::kLeftToleranceWindow);
  }
  if (!motor_on()) return {}; // an error above switched it off

  const double vel = velocity_rad_s;
  const double lim_pos = drive.motor.max_torque_Nm(vel, supply_V, +1.0);
  const double lim_neg = drive.motor.max_torque_Nm(vel, supply_V, -1.0);
  torque_Nm = controller.update(setpoint, measured, inertia_kgm2, lim_pos, lim_neg, dt_s);
  torque_limit_Nm = torque_Nm >= 0 ? lim_pos : lim_neg;
  return MotorCommand{torque_Nm, true};
}

double Device::Impl::user_deg(int64_t phys_counts) const {
  return internal_counts_to_deg(user_position(phys_counts, dir(), origin));
}

double Device::Impl::setpoint_user_deg() const {
  return motor_on() ? rad_to_deg(dir() * setpoint.pos_rad) - internal_counts_to_deg(origin)
                    : internal_counts_to_deg(user_now());
}

// Move records (issue 13, manual 3.5.2 Fig. 3): every control step, on the
// encoder reading, with the set latched at T3. Done ends a record at (f);
// any other way out of Busy (an error, the motor off) ends it without a
// settling time. A completed move stays held while its target is.
void Device::Impl::record_move_step() {
  if (!move_recorder.open() && !move_recorder.holding()) return; // the common case: nothing more per step
  const double position = internal_counts_to_deg(user_now());
  const double error_deg = tracking.step_error_deg;
  if (move_recorder.open()) {
    move_recorder.step(time_ns, error_deg, position, state == State::Busy && phase == MotionPhase::Travel);
    if (state == State::Done) {
      move_recorder.finish(time_ns, MoveOutcome::Done, position);
    } else if (state != State::Busy) {
      move_recorder.finish(time_ns, faults.any_error() ? MoveOutcome::Error : MoveOutcome::MotorOff, position,
                           faults.error_byte());
    }
  } else if (state == State::Done || state == State::Ready || state == State::Busy) {
    move_recorder.step(time_ns, error_deg, position, false);
  } else {
    move_recorder.release();
  }
}

} // namespace sreh
