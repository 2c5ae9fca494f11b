// Planner: closed-form travel times per case, continuity, limits, exact end
// (manual 3.5.3-3.5.6, 3.2 transition 4).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "device_logic/planner.hpp"
#include "device_logic/units.hpp"

namespace sreh {
namespace {

constexpr double kOneCount_rad = 2.0 * kPi / static_cast<double>(kInternalCountsPerRev);

double sum(const std::array<double, 7>& a) {
  double s = 0;
  for (double x : a) s += x;
  return s;
}

// Every sample (dense + both sides of every phase boundary) within the limits.
void expect_within_limits(const Profile& p, const MotionLimits& l, double rel_tol = 1e-9) {
  const double tv = l.v_max_rad_s * (1 + rel_tol) + 1e-12;
  const double ta = l.a_max_rad_s2 * (1 + rel_tol) + 1e-12;
  const double tj = l.j_max_rad_s3 * (1 + rel_tol);
  const int n = 64;
  for (int k = 0; k <= n; ++k) {
    const KinematicState s = p.at(p.duration_s() * k / n);
    ASSERT_LE(std::abs(s.vel_rad_s), tv);
    ASSERT_LE(std::abs(s.acc_rad_s2), ta);
    ASSERT_LE(std::abs(s.jerk_rad_s3), tj);
  }
  for (double j : p.phase_jerks_rad_s3()) ASSERT_LE(std::abs(j), tj);
}

TEST(Planner, LimitsFromParameterSetFollowTheManual_3_5_4_and_3_5_5) {
  // Factory set 1 (manual 6.2, index 65): 3000 deg/s, 100 %, 100 %, 0 g cm^2.
  const MotionLimits l = limits_from_parameter_set(3000.0, 100.0, 100.0, 0.0);
  EXPECT_DOUBLE_EQ(l.v_max_rad_s, deg_to_rad(3000.0));
  EXPECT_DOUBLE_EQ(l.a_max_rad_s2, 0.485 / 0.115e-3);
  EXPECT_DOUBLE_EQ(l.j_max_rad_s3, 0.485 / 0.115e-3 / 0.010); // alpha100 in 10 ms
  const MotionLimits h = limits_from_parameter_set(100.0, 50.0, 20.0, 15000.0);
  const double alpha100 = 0.485 / (0.115e-3 + 1.5e-3);
  EXPECT_DOUBLE_EQ(h.a_max_rad_s2, 0.5 * alpha100);
  EXPECT_DOUBLE_EQ(h.j_max_rad_s3, 0.2 * alpha100 / 0.010);
  EXPECT_TRUE(h.valid());
  EXPECT_FALSE(MotionLimits{}.valid());
}

TEST(Planner, VelocityAndAccelerationReachedTravelTime) {
  const MotionLimits l{10.0, 100.0, 1000.0}; // a/j = 0.1 s, v/a = 0.1 s
  const double d = 5.0;
  const Profile p = Profile::rest_to_rest(d, l);
  // T = d/v + v/a + a/j for the full seven-phase case.
  EXPECT_NEAR(p.duration_s(), d / 10.0 + 10.0 / 100.0 + 100.0 / 1000.0, 1e-12);
  const auto& ph = p.phase_durations_s();
  EXPECT_NEAR(ph[0], 0.1, 1e-12);
  EXPECT_NEAR(ph[1], 0.0, 1e-12); // v/a - a/j = 0: exactly on the border
  EXPECT_NEAR(ph[3], 0.5 - 0.2, 1e-12);
  EXPECT_DOUBLE_EQ(p.peak_velocity_rad_s(), 10.0);
  const MotionLimits l2{10.0, 50.0, 1000.0};
  const Profile q = Profile::rest_to_rest(d, l2);
  EXPECT_NEAR(q.duration_s(), d / 10.0 + 10.0 / 50.0 + 50.0 / 1000.0, 1e-12);
  EXPECT_NEAR(q.phase_durations_s()[1], 0.2 - 0.05, 1e-12);
}

TEST(Planner, OnlyAccelerationReachedTravelTime) {
  const MotionLimits l{100.0, 100.0, 1000.0};
  const double d = 5.0; // 2 a^3/j^2 = 2 <= d < d_v = 110
  const Profile p = Profile::rest_to_rest(d, l);
  // Peak speed from d = vp (vp/a + a/j), found here by bisection (independent).
  double lo = 0, hi = 100;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mid * (mid / 100.0 + 0.1) < d ? lo : hi) = mid;
  }
  EXPECT_NEAR(p.peak_velocity_rad_s(), lo, 1e-9);
  EXPECT_NEAR(p.duration_s(), 2.0 * (lo / 100.0 + 0.1), 1e-9);
  EXPECT_EQ(p.phase_durations_s()[3], 0.0);
  EXPECT_GT(p.phase_durations_s()[1], 0.0);
  EXPECT_NEAR(p.at(p.phase_durations_s()[0] + 0.5 * p.phase_durations_s()[1]).acc_rad_s2, 100.0, 1e-9);
}

TEST(Planner, OnlyVelocityReachedTravelTime) {
  const MotionLimits l{1.0, 100.0, 1000.0}; // v j = 1000 < a^2: a_max never reached
  const double d = 2.0;
  const Profile p = Profile::rest_to_rest(d, l);
  EXPECT_NEAR(p.duration_s(), d / 1.0 + 2.0 * std::sqrt(1.0 / 1000.0), 1e-12);
  EXPECT_EQ(p.phase_durations_s()[1], 0.0);
  EXPECT_NEAR(p.peak_velocity_rad_s(), 1.0, 1e-12);
}

TEST(Planner, NeitherLimitReachedTravelTime) {
  const MotionLimits l{100.0, 100.0, 1000.0};
  const double d = 0.5; // < 2 a^3/j^2 = 2
  const Profile p = Profile::rest_to_rest(d, l);
  EXPECT_NEAR(p.duration_s(), 4.0 * std::cbrt(d / 2000.0), 1e-12);
  EXPECT_EQ(p.phase_durations_s()[1], 0.0);
  EXPECT_EQ(p.phase_durations_s()[3], 0.0);
  EXPECT_DOUBLE_EQ(p.at(p.duration_s()).pos_rad, d);
}

TEST(Planner, OneCountMoveEndsExactlyOnTheCount) {
  // The smallest move: one internal count, 2 pi / 2^19 rad (manual 6.2, 64.5).
  const MotionLimits l = limits_from_parameter_set(3000.0, 100.0, 100.0, 0.0);
  for (double d : {kOneCount_rad, -kOneCount_rad}) {
    const Profile p = Profile::rest_to_rest(d, l);
    EXPECT_NEAR(p.duration_s(), 4.0 * std::cbrt(std::abs(d) / (2.0 * l.j_max_rad_s3)), 1e-15);
    EXPECT_GT(p.duration_s(), 0.0);
    const KinematicState e = p.at(p.duration_s());
    EXPECT_EQ(e.pos_rad, d);
    EXPECT_EQ(e.vel_rad_s, 0.0);
    EXPECT_EQ(e.acc_rad_s2, 0.0);
    EXPECT_EQ(p.end_position_rad(), d);
    expect_within_limits(p, l);
  }
}

TEST(Planner, ZeroLengthMoveIsEmpty) {
  const Profile p = Profile::rest_to_rest(0.0, MotionLimits{1, 1, 1});
  EXPECT_EQ(p.duration_s(), 0.0);
  EXPECT_EQ(sum(p.phase_durations_s()), 0.0);
  const KinematicState s = p.at(0.3);
  EXPECT_EQ(s.pos_rad, 0.0);
  EXPECT_EQ(s.vel_rad_s, 0.0);
  EXPECT_EQ(p.peak_velocity_rad_s(), 0.0);
}

TEST(Planner, InvalidLimitsAreRefusedNamingTheLimit) {
  const auto message = [](const auto& plan) {
    try {
      plan();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const MotionLimits ok{1, 1, 1};
  EXPECT_NE(message([] { Profile::rest_to_rest(1.0, MotionLimits{0, 1, 1}); }).find("v_max_rad_s"), std::string::npos);
  EXPECT_NE(message([] { Profile::rest_to_rest(1.0, MotionLimits{1, -1, 1}); }).find("a_max_rad_s2"), std::string::npos);
  EXPECT_NE(message([] { Profile::rest_to_rest(1.0, MotionLimits{1, 1, NAN}); }).find("j_max_rad_s3"), std::string::npos);
  EXPECT_NE(message([] { Profile::stop(KinematicState{0, 1, 0, 0}, MotionLimits{}); }).find("Profile::stop"),
            std::string::npos);
  EXPECT_NE(message([&] { Profile::rest_to_rest(INFINITY, ok); }).find("distance"), std::string::npos);
  EXPECT_NE(message([&] { Profile::stop(KinematicState{0, NAN, 0, 0}, ok); }).find("start state"), std::string::npos);
  // A zero distance with valid limits is a move of no length, not an error.
  EXPECT_EQ(message([&] { EXPECT_EQ(Profile::rest_to_rest(0.0, ok).duration_s(), 0.0); }), "no error");
}

TEST(Planner, NegativeMoveMirrorsPositive) {
  const MotionLimits l = limits_from_parameter_set(1000.0, 60.0, 30.0, 2000.0);
  const Profile p = Profile::rest_to_rest(deg_to_rad(90.0), l);
  const Profile n = Profile::rest_to_rest(-deg_to_rad(90.0), l);
  EXPECT_EQ(p.duration_s(), n.duration_s());
  EXPECT_EQ(p.peak_velocity_rad_s(), -n.peak_velocity_rad_s());
  for (int k = 0; k <= 100; ++k) {
    const double t = p.duration_s() * k / 100.0;
    EXPECT_NEAR(p.at(t).pos_rad, -n.at(t).pos_rad, 1e-12);
    EXPECT_NEAR(p.at(t).vel_rad_s, -n.at(t).vel_rad_s, 1e-12);
    EXPECT_NEAR(p.at(t).acc_rad_s2, -n.at(t).acc_rad_s2, 1e-9);
  }
  EXPECT_EQ(n.at(n.duration_s()).pos_rad, -deg_to_rad(90.0));
}

TEST(Planner, ContinuousAcrossPhaseBoundaries) {
  const MotionLimits l = limits_from_parameter_set(3000.0, 100.0, 100.0, 500.0);
  for (double d : {deg_to_rad(720.0), deg_to_rad(30.0), deg_to_rad(0.5)}) {
    const Profile p = Profile::rest_to_rest(d, l);
    double t = 0;
    for (double dur : p.phase_durations_s()) {
      t += dur;
      const double eps = 1e-9;
      const KinematicState a = p.at(t - eps);
      const KinematicState b = p.at(t + eps);
      const double scale = std::abs(d);
      EXPECT_NEAR(a.pos_rad, b.pos_rad, 1e-12 * scale + 2 * eps * l.v_max_rad_s);
      EXPECT_NEAR(a.vel_rad_s, b.vel_rad_s, 1e-10 * l.v_max_rad_s + 2 * eps * l.a_max_rad_s2);
      EXPECT_NEAR(a.acc_rad_s2, b.acc_rad_s2, 1e-9 * l.a_max_rad_s2 + 2 * eps * l.j_max_rad_s3);
    }
    // at(duration) is the end at rest; clamped past it and before 0.
    EXPECT_EQ(p.at(p.duration_s()).pos_rad, d);
    EXPECT_EQ(p.at(p.duration_s() + 1.0).pos_rad, d);
    EXPECT_EQ(p.at(-1.0).pos_rad, 0.0);
    EXPECT_EQ(p.at(p.duration_s()).jerk_rad_s3, 0.0);
  }
}

// Fixed-seed property test over random moves and parameter sets (docs/style.md 14).
TEST(Planner, RandomMovesRespectLimitsAndEndExactly) {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> speed(0.1, 4300.0), pct(0.1, 100.0), load(0.0, 15000.0);
  std::uniform_real_distribution<double> log_dist(-6.0, 4.0); // 1e-6 .. 1e4 rad
  std::bernoulli_distribution neg(0.5);
  for (int i = 0; i < 100000; ++i) {
    const MotionLimits l = limits_from_parameter_set(speed(rng), pct(rng), pct(rng), load(rng));
    double d = std::pow(10.0, log_dist(rng));
    if (i % 97 == 0) d = kOneCount_rad * static_cast<double>(1 + i % 5);
    if (neg(rng)) d = -d;
    const Profile p = Profile::rest_to_rest(d, l);
    ASSERT_EQ(p.at(p.duration_s()).pos_rad, d) << i;
    ASSERT_EQ(p.end_position_rad(), d);
    ASSERT_EQ(p.at(p.duration_s()).vel_rad_s, 0.0);
    ASSERT_NEAR(sum(p.phase_durations_s()), p.duration_s(), 1e-12 * p.duration_s());
    for (double dur : p.phase_durations_s()) ASSERT_GE(dur, 0.0);
    ASSERT_LE(std::abs(p.peak_velocity_rad_s()), l.v_max_rad_s * (1 + 1e-9));
    // Dense check on a subset (cost), the limits on all.
    if (i % 10 == 0) expect_within_limits(p, l);
    // Never moves backwards: velocity keeps the sign of the distance.
    const KinematicState mid = p.at(0.5 * p.duration_s());
    ASSERT_GT(mid.vel_rad_s * d, 0.0);
    ASSERT_NEAR(mid.pos_rad, 0.5 * d, 1e-9 * std::abs(d)); // symmetric profile
  }
}

// Time-optimality sanity: no profile can beat the optimum of a relaxed
// problem (one limit dropped), and each case meets one such bound exactly
// where the relaxed optimum is feasible.
TEST(Planner, TravelTimeRespectsRelaxedLowerBounds) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> speed(0.1, 4300.0), pct(0.1, 100.0), load(0.0, 15000.0);
  std::uniform_real_distribution<double> log_dist(-5.0, 3.0);
  for (int i = 0; i < 20000; ++i) {
    const MotionLimits l = limits_from_parameter_set(speed(rng), pct(rng), pct(rng), load(rng));
    const double d = std::pow(10.0, log_dist(rng));
    const double t = Profile::rest_to_rest(d, l).duration_s();
    const double only_v = d / l.v_max_rad_s;
    const double only_a = 2.0 * std::sqrt(d / l.a_max_rad_s2);
    const double only_j = 4.0 * std::cbrt(d / (2.0 * l.j_max_rad_s3));
    ASSERT_GE(t * (1 + 1e-12), std::max({only_v, only_a, only_j}));
    ASSERT_GE(t * (1 + 1e-12), only_j);
    // Jerk-only optimum is the answer whenever its peaks stay within limits.
    const double tj = std::cbrt(d / (2.0 * l.j_max_rad_s3));
    if (l.j_max_rad_s3 * tj <= l.a_max_rad_s2 && l.j_max_rad_s3 * tj * tj <= l.v_max_rad_s) {
      ASSERT_NEAR(t, only_j, 1e-9 * t);
    }
  }
}

// Brute force over the symmetric seven-phase family (jerk time, acceleration
// hold, cruise): nothing 1 % faster than the planned profile meets the
// distance inside the limits.
TEST(Planner, NoFasterProfileFoundByGridSearch) {
  const MotionLimits cases[] = {{10.0, 100.0, 1000.0}, {100.0, 100.0, 1000.0}, {1.0, 100.0, 1000.0},
                                limits_from_parameter_set(3000.0, 100.0, 100.0, 0.0),
                                limits_from_parameter_set(500.0, 30.0, 5.0, 8000.0)};
  for (const MotionLimits& l : cases) {
    for (double d : {0.01, 0.3, 1.0, 5.0}) {
      const double t_opt = Profile::rest_to_rest(d, l).duration_s();
      const double t_try = 0.99 * t_opt;
      const int n = 400;
      double best = 0; // farthest distance reachable in t_try
      for (int a = 0; a <= n; ++a) {
        const double tj = std::min(l.a_max_rad_s2 / l.j_max_rad_s3, t_try / 4.0) * a / n;
        for (int b = 0; b <= n; ++b) {
          const double ta = (t_try - 4.0 * tj) / 2.0 * b / n;
          const double tv = t_try - 4.0 * tj - 2.0 * ta;
          const double vp = l.j_max_rad_s3 * tj * tj + l.j_max_rad_s3 * tj * ta;
          if (vp > l.v_max_rad_s * (1 + 1e-12)) continue;
          best = std::max(best, vp * (2.0 * tj + ta) + vp * tv);
        }
      }
      EXPECT_LT(best, d) << "faster profile exists for d=" << d;
    }
  }
}

TEST(Planner, StopFromCruiseIsTimeOptimal) {
  const MotionLimits l{10.0, 50.0, 1000.0};
  // v0 >= a^2/j: full deceleration reached, T = v0/a + a/j.
  const Profile p = Profile::stop(KinematicState{1.0, 8.0, 0.0, 0.0}, l);
  EXPECT_NEAR(p.duration_s(), 8.0 / 50.0 + 0.05, 1e-12);
  EXPECT_NEAR(p.end_position_rad(), 1.0 + 8.0 * p.duration_s() / 2.0, 1e-12); // symmetric braking
  // v0 < a^2/j: T = 2 sqrt(v0/j).
  const Profile q = Profile::stop(KinematicState{0.0, -2.0, 0.0, 0.0}, l);
  EXPECT_NEAR(q.duration_s(), 2.0 * std::sqrt(2.0 / 1000.0), 1e-12);
  EXPECT_LT(q.end_position_rad(), 0.0);
  // At rest already: nothing to do, position kept.
  const Profile r = Profile::stop(KinematicState{2.5, 0.0, 0.0, 0.0}, l);
  EXPECT_EQ(r.duration_s(), 0.0);
  EXPECT_EQ(r.at(0.0).pos_rad, 2.5);
}

TEST(Planner, StopWhileAcceleratingRampsDownFirst) {
  const MotionLimits l{10.0, 100.0, 1000.0};
  const KinematicState from{0.0, 3.0, 100.0, 1000.0};
  const Profile p = Profile::stop(from, l);
  // Velocity first rises while the acceleration ramps down through zero.
  EXPECT_NEAR(p.peak_velocity_rad_s(), 3.0 + 100.0 * 100.0 / 2000.0, 1e-12);
  EXPECT_NEAR(p.at(0).acc_rad_s2, 100.0, 0.0);
  const KinematicState e = p.at(p.duration_s());
  EXPECT_EQ(e.vel_rad_s, 0.0);
  EXPECT_EQ(e.acc_rad_s2, 0.0);
  expect_within_limits(p, l);
}

TEST(Planner, StopWithAccelerationBeyondLimitComesBackInside) {
  const MotionLimits l{30.0, 100.0, 1000.0};
  // Braking at 150 (> a_max) with plenty of speed left (20 > 150^2 / 2j):
  // back to -100 at full jerk, hold, ramp out.
  const Profile p = Profile::stop(KinematicState{0.0, 20.0, -150.0, 0.0}, l);
  EXPECT_NEAR(p.duration_s(), 0.05 + (20.0 - 11.25) / 100.0 + 0.1, 1e-12);
  EXPECT_NEAR(p.phase_durations_s()[0], 0.05, 1e-12);
  EXPECT_GT(p.phase_jerks_rad_s3()[0], 0.0);
  EXPECT_NEAR(p.at(0.06).acc_rad_s2, -100.0, 1e-9);
  EXPECT_EQ(p.at(p.duration_s()).vel_rad_s, 0.0);
  // Accelerating at 150 (> a_max) forwards: ramps down through the limit.
  const Profile q = Profile::stop(KinematicState{0.0, 5.0, 150.0, 0.0}, l);
  EXPECT_LT(q.phase_jerks_rad_s3()[0], 0.0);
  EXPECT_EQ(q.at(q.duration_s()).vel_rad_s, 0.0);
  for (int k = 0; k <= 100; ++k) EXPECT_LE(q.at(q.duration_s() * k / 100.0).acc_rad_s2, 150.0 + 1e-9);
}

TEST(Planner, StopWhenBrakingWouldOvershootReversesJerk) {
  const MotionLimits l{10.0, 100.0, 1000.0};
  // Slow forwards but braking hard: ramping the acceleration straight to zero
  // would end at negative speed, so the acceleration swings positive.
  const KinematicState from{0.0, 0.5, -80.0, 0.0};
  const Profile p = Profile::stop(from, l);
  EXPECT_GT(p.phase_jerks_rad_s3()[0], 0.0);
  const KinematicState e = p.at(p.duration_s());
  EXPECT_EQ(e.vel_rad_s, 0.0);
  EXPECT_EQ(e.acc_rad_s2, 0.0);
  expect_within_limits(p, l);
  // Exactly balanced: one jerk phase to zero acceleration.
  const double v0 = 80.0 * 80.0 / 2000.0;
  const Profile q = Profile::stop(KinematicState{0.0, v0, -80.0, 0.0}, l);
  EXPECT_NEAR(q.duration_s(), 0.08, 1e-12);
}

TEST(Planner, RandomStopsEndAtRestWithinLimits) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> speed(0.1, 4300.0), pct(0.1, 100.0), load(0.0, 15000.0), u(-1.0, 1.0);
  for (int i = 0; i < 100000; ++i) {
    const MotionLimits l = limits_from_parameter_set(speed(rng), pct(rng), pct(rng), load(rng));
    const KinematicState from{u(rng), u(rng) * l.v_max_rad_s, u(rng) * l.a_max_rad_s2, 0.0};
    const Profile p = Profile::stop(from, l);
    const KinematicState e = p.at(p.duration_s());
    ASSERT_EQ(e.vel_rad_s, 0.0);
    ASSERT_EQ(e.acc_rad_s2, 0.0);
    ASSERT_EQ(e.pos_rad, p.end_position_rad());
    // Just before the end the state is at rest to rounding (continuity).
    const double dt = p.duration_s() * 1e-12;
    const KinematicState pre = p.at(p.duration_s() - dt);
    ASSERT_NEAR(pre.vel_rad_s, 0.0, 1e-9 * l.v_max_rad_s + dt * l.a_max_rad_s2);
    ASSERT_NEAR(pre.acc_rad_s2, 0.0, 1e-9 * l.a_max_rad_s2 + 2 * dt * l.j_max_rad_s3);
    // Speed never exceeds what it had plus what the ramp-down adds (a0^2 / 2j).
    const double bound = std::abs(from.vel_rad_s) + from.acc_rad_s2 * from.acc_rad_s2 / (2 * l.j_max_rad_s3);
    ASSERT_LE(std::abs(p.peak_velocity_rad_s()), bound * (1 + 1e-9) + 1e-12);
    if (i % 10 == 0) {
      const MotionLimits relaxed{bound * 1.0000001 + 1e-9, l.a_max_rad_s2, l.j_max_rad_s3};
      expect_within_limits(p, relaxed);
    }
  }
}

} // namespace
} // namespace sreh
