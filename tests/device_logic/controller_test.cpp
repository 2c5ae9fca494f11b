// Position controller against a simple plant (no MuJoCo): an ideal rigid
// inertia, semi-implicit Euler at 0.1 ms, Coulomb + viscous friction, the
// encoder quantised to 2^19 counts/rev, and the MotorModel torque limit.
// manual 3.5.3 (speed vs voltage), 3.5.4/3.5.6 (configured load), 3.5.7/3.5.8
// (default tolerance 0.1 deg, wait 25 ms, timeout 100 ms), 6.2 index 87
// (default max tracking error 1 deg).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>
#include <utility>

#include "device_logic/motor_model.hpp"
#include "device_logic/planner.hpp"
#include "device_logic/position_controller.hpp"
#include "device_logic/settling.hpp"
#include "device_logic/units.hpp"
#include "tests/device_logic/device_rig.hpp"

namespace sreh {
using sreh::test::card_drive;
namespace {

struct PlantSpec {
  double actual_load_gcm2 = 0;
  double configured_load_gcm2 = 0;
  double supply_V = 24.0;
  double coulomb_Nm = 0.01;      // test plant friction, not the twin's
  double viscous_Nms = 1e-5;
  ControllerGains gains = card_drive().gains;
  double dt_s = 1e-4;
};

struct MoveResult {
  double max_tracking_error_rad = 0; // |setpoint - encoder| over travel and settling
  double travel_s = 0;
  double settling_s = -1;            // (b)..(f), -1 if not settled
  SettlingResult result = SettlingResult::Settling;
  double final_error_rad = 0;
  double peak_torque_Nm = 0;
  double peak_speed_rad_s = 0;
};

class RigidPlant {
 public:
  explicit RigidPlant(const PlantSpec& s) : s_(s), j_(kInternalInertia_kgm2 + gcm2_to_kgm2(s.actual_load_gcm2)) {}
  double encoder_rad() const {
    return internal_counts_to_rad(static_cast<int64_t>(std::llround(pos_ / (2.0 * kPi) * static_cast<double>(kInternalCountsPerRev))));
  }
  double velocity() const { return vel_; }
  // Applies the motor torque (clamped to what the motor can do at the true
  // speed) for one step.
  void step(double torque_cmd_Nm) {
    const double torque = motor_.saturate(torque_cmd_Nm, vel_, s_.supply_V);
    double v = vel_;
    if (v == 0.0 && std::abs(torque) <= s_.coulomb_Nm) { // static friction holds
      return;
    }
    const double dir = v != 0.0 ? (v > 0 ? 1.0 : -1.0) : (torque > 0 ? 1.0 : -1.0);
    const double acc = (torque - s_.coulomb_Nm * dir - s_.viscous_Nms * v) / j_;
    double v_new = v + acc * s_.dt_s;
    if (v != 0.0 && v_new * v < 0.0) v_new = 0.0; // friction stops, it does not reverse
    vel_ = v_new;
    pos_ += vel_ * s_.dt_s;
  }

 private:
  PlantSpec s_;
  double j_;
  MotorModel motor_ = card_drive().motor;
  double pos_ = 0;
  double vel_ = 0;
};

// One rest-to-rest move with the default settling parameters unless given.
MoveResult simulate_move(double distance_rad, const MotionLimits& limits, const PlantSpec& spec,
                                SettlingParameters settle = {deg_to_rad(0.1), 0.025, 0.1, true},
                                double max_settle_s = 1.0) {
  RigidPlant plant(spec);
  PositionController ctrl(spec.gains);
  MotorModel motor = card_drive().motor;
  const double j_conf = kInternalInertia_kgm2 + gcm2_to_kgm2(spec.configured_load_gcm2);
  const Profile profile = Profile::rest_to_rest(distance_rad, limits);
  MoveResult r;
  r.travel_s = profile.duration_s();
  ctrl.reset(plant.encoder_rad());
  SettlingMonitor monitor;
  bool settling = false;
  const long steps_travel = static_cast<long>(std::ceil(profile.duration_s() / spec.dt_s));
  const long steps_max = steps_travel + static_cast<long>(max_settle_s / spec.dt_s);
  for (long k = 0; k <= steps_max; ++k) {
    const double t = static_cast<double>(k) * spec.dt_s;
    const KinematicState sp = profile.at(t);
    const double meas = plant.encoder_rad();
    const double err = sp.pos_rad - meas;
    r.max_tracking_error_rad = std::max(r.max_tracking_error_rad, std::abs(err));
    r.final_error_rad = err;
    if (k >= steps_travel) {
      if (!settling) {
        monitor.start(settle);
        settling = true;
        r.result = monitor.update(err, 0.0);
      } else {
        r.result = monitor.update(err, spec.dt_s);
      }
      if (r.result != SettlingResult::Settling) {
        if (r.result == SettlingResult::Done) r.settling_s = monitor.settling_time_s();
        break;
      }
    }
    const double v_est = ctrl.velocity_estimate_rad_s();
    const double torque = ctrl.update(sp, meas, j_conf, motor.max_torque_Nm(v_est, spec.supply_V, 1.0),
                                      motor.max_torque_Nm(v_est, spec.supply_V, -1.0), spec.dt_s);
    r.peak_torque_Nm = std::max(r.peak_torque_Nm, std::abs(torque));
    r.peak_speed_rad_s = std::max(r.peak_speed_rad_s, std::abs(plant.velocity()));
    plant.step(torque);
  }
  return r;
}


constexpr double kMaxTrackingError_rad = deg_to_rad(1.0); // manual 6.2 index 87.1 default

ControllerGains without_delay() {
  ControllerGains g = card_drive().gains;
  g.delay_periods = 0;
  return g;
}

// A-CTRL-1: the drive tunes for the configured load; a heavier configured
// load gets a lower velocity bandwidth, and the loop gain the motor side
// must carry stays inside the discrete bound for the rotor alone.
TEST(Controller, GainScheduleLowersBandwidthWithConfiguredLoad) {
  const ControllerGains g = card_drive().gains;
  double last_wv = 1e300;
  double last_kv = 0;
  for (double load : {0.0, 1000.0, 5000.0, 10000.0, 15000.0}) {
    const double j = kInternalInertia_kgm2 + gcm2_to_kgm2(load);
    const double wv = g.velocity_bandwidth_for(j);
    EXPECT_LT(wv, last_wv) << load;
    EXPECT_GT(j * wv, last_kv) << load; // the gain itself still grows with J
    last_wv = wv;
    last_kv = j * wv;
    // mujoco.md: a discrete D term is stable only for Kd < 2 J / dt; above
    // the two-mass resonance the velocity loop sees the rotor alone (A-TWIN-20:
    // J_m = 1.0e-4 kg m^2), so that bound applies to it.
    EXPECT_LT(j * wv, 2.0 * 1.0e-4 / 1e-4) << load;
  }
  EXPECT_DOUBLE_EQ(g.velocity_bandwidth_for(kInternalInertia_kgm2), g.velocity_bandwidth_rad_s);
}

// A-CTRL-7: the torque computed from a sample reaches the current loop
// `delay_periods` control periods later (3 by default: encoder transfer,
// computation, PWM reload).
TEST(Controller, OutputIsDelayedByTheLoopDelay) {
  PositionController delayed(card_drive().gains);
  PositionController direct(without_delay());
  const int n = delayed.gains().delay_periods;
  ASSERT_EQ(n, 3);
  delayed.reset(0.0);
  direct.reset(0.0);
  const double j = 2e-4;
  std::vector<double> history;
  for (int k = 0; k < 20; ++k) {
    const KinematicState sp{1e-4 * k, 0.0, 50.0 * (k % 3), 0};
    const double a = delayed.update(sp, 0.0, j, 1.0, 1.0, 1e-4);
    const double b = direct.update(sp, 0.0, j, 1.0, 1.0, 1e-4);
    const double expected = k >= n ? history[static_cast<std::size_t>(k - n)] : 0.0;
    EXPECT_EQ(a, expected) << k;
    history.push_back(b);
  }
}

TEST(Controller, FeedForwardAloneWhenOnTrack) {
  PositionController c(without_delay());
  c.reset(0.0);
  const double j = 2e-4;
  // Setpoint at rest where the axis is: zero torque. Accelerating setpoint on
  // the measured position: torque is J * acc.
  EXPECT_EQ(c.update(KinematicState{0, 0, 0, 0}, 0.0, j, 1.0, 1.0, 1e-4), 0.0);
  EXPECT_NEAR(c.update(KinematicState{0, 0, 100.0, 0}, 0.0, j, 1.0, 1.0, 1e-4), j * 100.0, 1e-12);
}

TEST(Controller, SaturatesAtDirectionalLimitsWithoutWindup) {
  PositionController c(without_delay());
  c.reset(0.0);
  const double j = kInternalInertia_kgm2;
  // A large error held for 0.5 s against the limit: the output is clamped to the
  // positive limit and the integrator does not wind beyond it.
  for (int k = 0; k < 5000; ++k) {
    const double t = c.update(KinematicState{1.0, 0, 0, 0}, 0.0, j, 0.3, 0.1, 1e-4);
    ASSERT_LE(t, 0.3);
    ASSERT_GE(t, -0.1);
  }
  EXPECT_TRUE(c.saturated());
  EXPECT_LE(c.integral_torque_Nm(), 0.3);
  // Error reverses: the torque leaves the positive limit at once (no stored windup).
  const double t = c.update(KinematicState{-1.0, 0, 0, 0}, 0.0, j, 0.3, 0.1, 1e-4);
  EXPECT_EQ(t, -0.1);
  // Negative limit is the other direction's own limit.
  EXPECT_GE(c.update(KinematicState{-1.0, 0, 0, 0}, 0.0, j, 0.3, 0.1, 1e-4), -0.1);
}

TEST(Controller, InvalidStepLeavesStateAlone) {
  PositionController c(card_drive().gains);
  c.reset(0.0);
  EXPECT_EQ(c.update(KinematicState{1.0, 0, 0, 0}, 0.0, 1e-4, 1, 1, 0.0), 0.0);
  EXPECT_EQ(c.update(KinematicState{NAN, 0, 0, 0}, 0.0, 1e-4, 1, 1, 1e-4), 0.0);
  EXPECT_EQ(c.integral_torque_Nm(), 0.0);
}

TEST(Controller, VelocityEstimateFollowsQuantisedEncoder) {
  PositionController c(card_drive().gains);
  c.reset(0.0);
  // Constant 10 rad/s through the quantised encoder: the estimate converges to it.
  const double count = 2.0 * kPi / static_cast<double>(kInternalCountsPerRev);
  for (int k = 1; k <= 200; ++k) {
    const double pos = std::round(10.0 * k * 1e-4 / count) * count;
    c.update(KinematicState{pos, 10.0, 0, 0}, pos, 1e-4, 1, 1, 1e-4);
  }
  EXPECT_NEAR(c.velocity_estimate_rad_s(), 10.0, 0.1);
}

// Default parameter sets (3000 deg/s, 100 %, 100 %) with the load configured
// correctly settle within the default tolerance, waiting time and timeout,
// over the whole load range (manual 3.5.6: 0..15000 g cm^2).
TEST(Controller, CorrectLoadTracksAndSettlesAcrossLoadRange) {
  for (double load : {0.0, 1000.0, 5000.0, 15000.0}) {
    for (double deg : {1.0, 90.0, -360.0}) {
      PlantSpec s;
      s.actual_load_gcm2 = load;
      s.configured_load_gcm2 = load;
      const MoveResult r = simulate_move(deg_to_rad(deg), limits_from_parameter_set(3000, 100, 100, load), s);
      EXPECT_EQ(r.result, SettlingResult::Done) << load << " g cm^2, " << deg << " deg";
      EXPECT_LT(r.max_tracking_error_rad, deg_to_rad(0.1)) << load << " g cm^2, " << deg << " deg";
      EXPECT_LE(r.settling_s, 0.05) << load << " g cm^2, " << deg << " deg";
      EXPECT_LT(std::abs(r.final_error_rad), deg_to_rad(0.1));
    }
  }
}

TEST(Controller, FourTimesHeavierActualLoadTracksMuchWorse) {
  // manual 3.5.6 / 7.2 error 3: a wrong load shows up as tracking error.
  for (double conf : {1000.0, 2000.0}) {
    PlantSpec right, wrong;
    right.actual_load_gcm2 = right.configured_load_gcm2 = conf;
    wrong.configured_load_gcm2 = conf;
    wrong.actual_load_gcm2 = 4.0 * conf;
    const MotionLimits l = limits_from_parameter_set(3000, 100, 100, conf);
    const MoveResult a = simulate_move(deg_to_rad(90.0), l, right);
    const MoveResult b = simulate_move(deg_to_rad(90.0), l, wrong);
    EXPECT_GT(b.max_tracking_error_rad, 20.0 * a.max_tracking_error_rad) << conf;
    EXPECT_GT(b.max_tracking_error_rad, kMaxTrackingError_rad) << conf;
  }
}

TEST(Controller, HeavyConfiguredLoadOnLightAxisLeadsAndOvershoots) {
  // The worst gain mismatch (15000 g cm^2 configured, none mounted): the
  // acceleration feed-forward is 14x too large, the axis runs ahead. At a
  // gentle 10 % acceleration the loop still settles (no instability; with
  // the 3-period loop delay, A-CTRL-7, it needs more than the default
  // 100 ms settling timeout, so 1 s here), with far more error than a
  // correct setting; at 100 % the error passes the 1 deg limit (manual
  // 7.2, 114.5).
  PlantSpec wrong;
  wrong.configured_load_gcm2 = 15000.0;
  PlantSpec right;
  const MoveResult gentle = simulate_move(deg_to_rad(90.0), limits_from_parameter_set(3000, 10, 100, 15000.0), wrong,
                                          SettlingParameters{deg_to_rad(0.1), 0.025, 1.0, true}, 2.0);
  const MoveResult reference =
      simulate_move(deg_to_rad(90.0), limits_from_parameter_set(3000, 10, 100, 15000.0), right);
  EXPECT_EQ(gentle.result, SettlingResult::Done);
  EXPECT_GT(gentle.max_tracking_error_rad, 5.0 * reference.max_tracking_error_rad);
  const MoveResult full = simulate_move(deg_to_rad(90.0), limits_from_parameter_set(3000, 100, 100, 15000.0), wrong);
  EXPECT_GT(full.max_tracking_error_rad, kMaxTrackingError_rad);
}

TEST(Controller, MaxSpeedFollowsAt24VButNotAt19V) {
  // manual 3.5.3: 4300 deg/s is reachable at the nominal 24 V; below, the
  // reachable speed falls with the voltage and too high a speed gives a
  // tracking error.
  const MotionLimits l = limits_from_parameter_set(4300, 100, 100, 0.0);
  PlantSpec at24, at19;
  at19.supply_V = 19.0;
  const MoveResult ok = simulate_move(deg_to_rad(1800.0), l, at24);
  EXPECT_EQ(ok.result, SettlingResult::Done);
  EXPECT_LT(ok.max_tracking_error_rad, deg_to_rad(0.1));
  EXPECT_NEAR(rad_to_deg(ok.peak_speed_rad_s), 4300.0, 10.0);
  const MoveResult bad = simulate_move(deg_to_rad(1800.0), l, at19);
  EXPECT_GT(bad.max_tracking_error_rad, kMaxTrackingError_rad);
  EXPECT_LT(rad_to_deg(bad.peak_speed_rad_s), 3600.0); // 4300 x 19/24 = 3404, no-load 3562
  // ~4300 x 19 / 24 still follows at 19 V (full acceleration, no load).
  const MoveResult slower = simulate_move(deg_to_rad(1800.0), limits_from_parameter_set(3300, 100, 100, 0.0), at19);
  EXPECT_LT(slower.max_tracking_error_rad, deg_to_rad(0.1));
}

TEST(Controller, MaxSpeedWithHeaviestLoadFollowsAt24V) {
  PlantSpec s;
  s.actual_load_gcm2 = s.configured_load_gcm2 = 15000.0;
  const MoveResult r = simulate_move(deg_to_rad(3600.0), limits_from_parameter_set(4300, 100, 100, 15000.0), s);
  EXPECT_EQ(r.result, SettlingResult::Done);
  EXPECT_LT(r.max_tracking_error_rad, deg_to_rad(0.1));
}

} // namespace
} // namespace sreh
