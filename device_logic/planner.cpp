// Closed-form time-optimal S-curves (manual 3.5, 3.2 transition 4).
// Rest to rest with symmetric limits: the classic three cases (v_max and
// a_max reached, only a_max or only v_max, neither), each solved directly.
#include "device_logic/planner.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "device_logic/units.hpp"

namespace sreh {
namespace {

bool finite_positive(double x) { return std::isfinite(x) && x > 0.0; }

// A planner asked to plan with a limit that is zero, negative or not a
// number is a caller's bug, not a move: say which limit, once.
void require_valid(const MotionLimits& l, const char* planner) {
  const auto fail = [&](const char* name, double v) {
    throw std::invalid_argument(std::string(planner) + ": " + name + " = " + std::to_string(v) +
                                " is not a finite positive number");
  };
  if (!finite_positive(l.v_max_rad_s)) fail("v_max_rad_s", l.v_max_rad_s);
  if (!finite_positive(l.a_max_rad_s2)) fail("a_max_rad_s2", l.a_max_rad_s2);
  if (!finite_positive(l.j_max_rad_s3)) fail("j_max_rad_s3", l.j_max_rad_s3);
}

// State after `t` seconds of constant jerk `j` from `b`.
KinematicState advance(const KinematicState& b, double j, double t) {
  KinematicState s;
  s.pos_rad = b.pos_rad + t * (b.vel_rad_s + t * (0.5 * b.acc_rad_s2 + t * (j / 6.0)));
  s.vel_rad_s = b.vel_rad_s + t * (b.acc_rad_s2 + t * (0.5 * j));
  s.acc_rad_s2 = b.acc_rad_s2 + t * j;
  s.jerk_rad_s3 = j;
  return s;
}

} // namespace

bool MotionLimits::valid() const {
  return finite_positive(v_max_rad_s) && finite_positive(a_max_rad_s2) && finite_positive(j_max_rad_s3);
}

MotionLimits limits_from_parameter_set(double speed_dps, double accel_pct, double jerk_pct, double load_gcm2) {
  const double alpha100 = alpha100_rad_s2(load_gcm2); // manual 3.5.4
  MotionLimits l;
  l.v_max_rad_s = deg_to_rad(speed_dps);                          // manual 3.5.3
  l.a_max_rad_s2 = accel_pct / 100.0 * alpha100;                  // manual 3.5.4
  l.j_max_rad_s3 = jerk_pct / 100.0 * alpha100 / kJerkRampTime_s; // manual 3.5.5
  return l;
}

void Profile::finish(const KinematicState& start) {
  t_start_[0] = 0.0;
  boundaries_[0] = start;
  for (int i = 0; i < 7; ++i) {
    t_start_[i + 1] = t_start_[i] + durations_[i];
    boundaries_[i].jerk_rad_s3 = jerks_[i];
    boundaries_[i + 1] = advance(boundaries_[i], jerks_[i], durations_[i]);
  }
  boundaries_[7].jerk_rad_s3 = 0.0;
  t_end_ = t_start_[7];
}

Profile Profile::rest_to_rest(double distance_rad, const MotionLimits& limits) {
  require_valid(limits, "Profile::rest_to_rest");
  if (!std::isfinite(distance_rad)) throw std::invalid_argument("Profile::rest_to_rest: the distance is not finite");
  Profile p;
  if (distance_rad == 0.0) return p;

  const double d = std::abs(distance_rad);
  const double v = limits.v_max_rad_s;
  const double a = limits.a_max_rad_s2;
  const double j = limits.j_max_rad_s3;

  double tj = 0; // jerk phase (0, 2, 4, 6)
  double ta = 0; // constant acceleration phase (1, 5)
  double tv = 0; // cruise (3)
  const bool a_reachable = v * j >= a * a; // a_max is reached before v_max
  // Distance of accelerating to v_max and back (symmetric: mean speed v/2 each way).
  const double d_v = a_reachable ? v * (v / a + a / j) : 2.0 * v * std::sqrt(v / j);
  if (d >= d_v) { // v_max reached
    if (a_reachable) {
      tj = a / j;
      ta = v / a - tj;
    } else {
      tj = std::sqrt(v / j);
    }
    tv = (d - d_v) / v;
  } else if (a_reachable && d >= 2.0 * a * a * a / (j * j)) {
    // a_max reached, v_max not: the peak speed vp solves vp^2 + vp a^2/j - a d = 0
    // (written in the cancellation-free form).
    tj = a / j;
    const double b = a * a / j;
    const double vp = 2.0 * a * d / (b + std::sqrt(b * b + 4.0 * a * d));
    ta = std::max(0.0, vp / a - tj);
  } else { // neither limit reached: d = 2 j tj^3
    tj = std::cbrt(d / (2.0 * j));
  }

  const double s = distance_rad > 0 ? 1.0 : -1.0;
  p.durations_ = {tj, ta, tj, tv, tj, ta, tj};
  p.jerks_ = {s * j, 0.0, -s * j, 0.0, -s * j, 0.0, s * j};
  p.finish(KinematicState{});
  // The profile is symmetric in time (pos(T - t) = D - pos(t)): the second
  // half mirrors the first, so the end is the distance exactly, not an
  // integration result (the device adds it to an integer count target).
  for (int i = 4; i < 8; ++i) {
    const KinematicState& m = p.boundaries_[7 - i];
    p.boundaries_[i].pos_rad = distance_rad - m.pos_rad;
    p.boundaries_[i].vel_rad_s = m.vel_rad_s;
    p.boundaries_[i].acc_rad_s2 = -m.acc_rad_s2;
  }
  p.end_pos_ = distance_rad;
  return p;
}

Profile Profile::stop(const KinematicState& from, const MotionLimits& limits) {
  Profile p;
  p.end_pos_ = from.pos_rad;
  p.boundaries_.fill(KinematicState{from.pos_rad, 0.0, 0.0, 0.0});
  require_valid(limits, "Profile::stop");
  if (!std::isfinite(from.vel_rad_s) || !std::isfinite(from.acc_rad_s2) || !std::isfinite(from.pos_rad)) {
    throw std::invalid_argument("Profile::stop: the start state is not finite");
  }
  if (from.vel_rad_s == 0.0 && from.acc_rad_s2 == 0.0) return p;

  const double a_max = limits.a_max_rad_s2;
  const double j = limits.j_max_rad_s3;
  // Velocity reached if the acceleration were ramped to zero at once.
  const double v_b = from.vel_rad_s + from.acc_rad_s2 * std::abs(from.acc_rad_s2) / (2.0 * j);
  // Mirror so that the braking acceleration is negative: s * (state).
  const double s = v_b > 0.0 ? 1.0 : (v_b < 0.0 ? -1.0 : (from.acc_rad_s2 > 0.0 ? 1.0 : -1.0));
  const double v0 = s * from.vel_rad_s;
  const double a0 = s * from.acc_rad_s2;

  double t1 = 0, t2 = 0, t3 = 0;
  double j1 = -j; // jerk of the first phase (mirrored frame)
  if (a0 < -a_max) {
    // Braking harder than allowed (A-MOTION-4): back to -a_max at full jerk,
    // hold, ramp out. v_b > 0 here, so the hold time is positive.
    j1 = j;
    t1 = (-a_max - a0) / j;
    t2 = std::max(0.0, v0 - a0 * a0 / (2.0 * j)) / a_max;
    t3 = a_max / j;
  } else {
    // Down to -ap, (hold), back up to 0: v0 + a0^2/(2j) - ap^2/j - ap*t2 = 0.
    const double ap_free = std::sqrt(std::max(0.0, j * v0 + 0.5 * a0 * a0));
    const double ap = std::min(ap_free, a_max);
    t1 = std::max(0.0, (a0 + ap) / j);
    t3 = ap / j;
    if (ap_free > a_max) t2 = std::max(0.0, (v0 + a0 * a0 / (2.0 * j) - a_max * a_max / j) / a_max);
  }
  p.durations_ = {t1, t2, t3, 0.0, 0.0, 0.0, 0.0};
  p.jerks_ = {s * j1, 0.0, s * j, 0.0, 0.0, 0.0, 0.0};
  p.finish(KinematicState{from.pos_rad, from.vel_rad_s, from.acc_rad_s2, 0.0});
  // Exactly at rest at the end, wherever that is.
  for (int i = 3; i < 8; ++i) {
    p.boundaries_[i].vel_rad_s = 0.0;
    p.boundaries_[i].acc_rad_s2 = 0.0;
    p.boundaries_[i].jerk_rad_s3 = 0.0;
  }
  p.end_pos_ = p.boundaries_[7].pos_rad;
  return p;
}

double Profile::peak_velocity_rad_s() const {
  double peak = boundaries_[0].vel_rad_s;
  const auto consider = [&peak](double v) {
    if (std::abs(v) > std::abs(peak)) peak = v;
  };
  for (int i = 0; i < 7; ++i) {
    if (durations_[i] <= 0.0) continue;
    const KinematicState& b = boundaries_[i];
    consider(boundaries_[i + 1].vel_rad_s);
    // Interior extremum where the acceleration crosses zero.
    if (jerks_[i] != 0.0) {
      const double tau = -b.acc_rad_s2 / jerks_[i];
      if (tau > 0.0 && tau < durations_[i]) consider(advance(b, jerks_[i], tau).vel_rad_s);
    }
  }
  return peak;
}

KinematicState Profile::at(double t_s) const {
  if (!(t_s < t_end_)) return boundaries_[7]; // also NaN: the end, at rest
  if (t_s <= 0.0) return boundaries_[0];
  int i = 0;
  while (i < 6 && t_s >= t_start_[i + 1]) ++i;
  return advance(boundaries_[i], jerks_[i], t_s - t_start_[i]);
}

} // namespace sreh
