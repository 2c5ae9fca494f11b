// Time-optimal jerk-limited (S-curve) point-to-point planner, manual 3.5.
// A value: limits and a move go in, a profile comes out (style.md 1).
// Positions in rad relative to the move's start, SI throughout.
#pragma once
#include <array>

namespace sreh {

struct MotionLimits {
  double v_max_rad_s = 0; // manual 3.5.3
  double a_max_rad_s2 = 0; // manual 3.5.4: accel% x alpha100%
  double j_max_rad_s3 = 0; // manual 3.5.5: jerk% x alpha100% / 10 ms
};

// Limits of a motion parameter set (manual 3.5.3-3.5.6) from the raw wire
// values: speed in 0.1 deg/s, accel and jerk in 0.1 %, load in g cm^2.
MotionLimits limits_from_parameter_set(double speed_dps, double accel_pct, double jerk_pct, double load_gcm2);

struct KinematicState {
  double pos = 0; // rad
  double vel = 0; // rad/s
  double acc = 0; // rad/s^2
  double jerk = 0; // rad/s^3
};

// Up to seven constant-jerk phases. Unused phases have zero duration.
class Profile {
 public:
  Profile() = default;

  // Rest to rest over `distance_rad` (any sign, zero allowed), time-optimal
  // for the limits.
  static Profile rest_to_rest(double distance_rad, const MotionLimits& limits);

  // From a moving state to rest as fast as the acceleration and jerk limits
  // allow (manual 3.2 transition 4). The end position is wherever it stops.
  static Profile stop(const KinematicState& from, const MotionLimits& limits);

  double duration_s() const { return t_end_; }
  const std::array<double, 7>& phase_durations_s() const { return durations_; }
  double end_position_rad() const { return end_pos_; }
  double peak_velocity_rad_s() const;

  // Sample at time t (clamped to [0, duration]); at(duration) is the end at rest.
  KinematicState at(double t_s) const;

 private:
  std::array<double, 7> durations_{};
  std::array<double, 7> jerks_{};              // jerk in each phase
  std::array<KinematicState, 8> boundaries_{}; // state at the start of each phase (and the end)
  std::array<double, 8> t_start_{};
  double t_end_ = 0;
  double end_pos_ = 0;
};

} // namespace sreh
