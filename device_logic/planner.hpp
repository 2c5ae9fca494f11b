// Time-optimal jerk-limited (S-curve) point-to-point planner, manual 3.5.
// A value: limits and a move go in, a profile comes out (docs/style.md 1).
// Positions in rad relative to the move's start, SI throughout.
// Closed form (no iteration): see docs/assumptions/motion.md A-MOTION-1..3.
#pragma once
#include <array>

namespace sreh {

struct MotionLimits {
  double v_max_rad_s = 0; // manual 3.5.3
  double a_max_rad_s2 = 0; // manual 3.5.4: accel% x alpha100%
  double j_max_rad_s3 = 0; // manual 3.5.5: jerk% x alpha100% / 10 ms

  // All three finite and > 0. The planners throw std::invalid_argument
  // (naming the limit) otherwise: an empty profile would look like a move
  // that is already done. The device never gets there: its limits come from
  // table rows whose minimum is above zero (manual 6.2).
  bool valid() const;
  bool operator==(const MotionLimits&) const = default;
};

// Limits of a motion parameter set (manual 3.5.3-3.5.6) in display units
// (the parameter table converts the raw wire values first): speed in deg/s,
// acceleration and jerk factors in %, configured load in g cm^2.
//   v_max = speed;  a_max = accel%/100 * alpha100%(load);
//   j_max = jerk%/100 * alpha100%(load) / 10 ms.
MotionLimits limits_from_parameter_set(double speed_dps, double accel_pct, double jerk_pct, double load_gcm2);

struct KinematicState {
  double pos_rad = 0;
  double vel_rad_s = 0;
  double acc_rad_s2 = 0;
  double jerk_rad_s3 = 0;
  bool operator==(const KinematicState&) const = default;
};

// Up to seven constant-jerk phases. Unused phases have zero duration.
class Profile {
 public:
  Profile() = default;

  // Rest to rest over `distance_rad` (any sign, zero allowed), time-optimal
  // for the limits. Phases: jerk up, const acc, jerk down, cruise, and the
  // mirror image; a limit that is not reached leaves its phase at zero.
  // at(duration_s()).pos_rad == distance_rad exactly (the device adds it to an
  // integer count target). A zero distance is an empty profile (duration
  // 0, end 0); invalid limits or a non-finite distance throw
  // std::invalid_argument.
  static Profile rest_to_rest(double distance_rad, const MotionLimits& limits);

  // From a moving state to rest as fast as the acceleration and jerk limits
  // allow (manual 3.2 transition 4). The end position is wherever it stops;
  // `from.pos_rad` is the start position (the profile's positions are absolute
  // in the caller's frame then, start = from.pos_rad). An acceleration already
  // beyond a_max is first brought back inside the limit at full jerk
  // (A-MOTION-4). Uses phases 0..2 only; the end is exactly vel = acc = 0.
  // Invalid limits or a non-finite state throw std::invalid_argument.
  static Profile stop(const KinematicState& from, const MotionLimits& limits);

  double duration_s() const { return t_end_; }
  const std::array<double, 7>& phase_durations_s() const { return durations_; }
  const std::array<double, 7>& phase_jerks_rad_s3() const { return jerks_; }
  double end_position_rad() const { return end_pos_; }
  // Signed velocity of largest magnitude over the whole profile (the cruise
  // velocity of a rest-to-rest move that reaches v_max).
  double peak_velocity_rad_s() const;

  // Sample at time t (clamped to [0, duration]); at(duration) is the end at rest.
  KinematicState at(double t_s) const;

  bool operator==(const Profile&) const = default;

 private:
  void finish(const KinematicState& start); // fills boundaries and times from durations/jerks

  std::array<double, 7> durations_{};
  std::array<double, 7> jerks_{};              // jerk in each phase
  std::array<KinematicState, 8> boundaries_{}; // state at the start of each phase (and the end)
  std::array<double, 8> t_start_{};
  double t_end_ = 0;
  double end_pos_ = 0;
};

} // namespace sreh
