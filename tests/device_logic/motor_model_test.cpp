// Motor torque-speed model (assumptions A-MOTOR-1..3, docs/assumptions/motion.md)
// against what the manual requires: M = 0.485 N m for alpha100% (3.5.4), the
// maximum speed 4300 deg/s reachable at 24 V, proportionally less below (3.5.3).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "device_logic/motor_model.hpp"
#include "device_logic/planner.hpp"
#include "device_logic/units.hpp"
#include "twin/module_model.hpp"

namespace sreh {
namespace {

// Highest speed at which the motor still gives `torque_Nm` motoring at `supply_V`.
double speed_with_torque_dps(const MotorModel& m, double torque_Nm, double supply_V) {
  double lo = 0, hi = deg_to_rad(10000.0);
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (m.max_torque_Nm(mid, supply_V, 1.0) >= torque_Nm ? lo : hi) = mid;
  }
  return rad_to_deg(lo);
}

// Smallest torque margin (available - needed) along a planned profile, with
// the configured load equal to the actual one and `friction_Nm` on top.
double min_margin_Nm(const MotorModel& m, double speed_dps, double load_gcm2, double supply_V,
                     double friction_Nm = 0.01) {
  const MotionLimits l = limits_from_parameter_set(speed_dps, 100, 100, load_gcm2);
  const Profile p = Profile::rest_to_rest(deg_to_rad(3600.0), l);
  const double j = kInternalInertia_kgm2 + gcm2_to_kgm2(load_gcm2);
  double margin = 1e9;
  for (int k = 0; k <= 20000; ++k) {
    const KinematicState s = p.at(p.duration_s() * k / 20000.0);
    const double need = j * s.acc_rad_s2 + friction_Nm * (s.vel_rad_s > 0 ? 1.0 : 0.0);
    const double sign = need >= 0 ? 1.0 : -1.0;
    margin = std::min(margin, m.max_torque_Nm(s.vel_rad_s, supply_V, sign) - std::abs(need));
  }
  return margin;
}

TEST(MotorModel, PeakTorqueAboveRatedTorque) {
  // manual 3.5.4: alpha100% needs M = 0.485 N m; the stage keeps headroom for control.
  const MotorModel m = default_module_model().drive.motor; // the model card's
  EXPECT_NEAR(m.peak_torque_Nm(), 0.60, 1e-12);
  EXPECT_GT(m.peak_torque_Nm(), kMotorTorque_Nm * 1.2);
}

TEST(MotorModel, NoLoadSpeedProportionalToVoltage) {
  // manual 3.5.3: the maximum possible speed decreases in proportion to the voltage.
  const MotorModel m = default_module_model().drive.motor; // the model card's
  const double at24 = speed_with_torque_dps(m, 1e-9, 24.0);
  EXPECT_NEAR(speed_with_torque_dps(m, 1e-9, 19.0) / at24, 19.0 / 24.0, 1e-6);
  EXPECT_NEAR(speed_with_torque_dps(m, 1e-9, 12.0) / at24, 12.0 / 24.0, 1e-6);
  EXPECT_GT(at24, 4300.0);                                // the maximum setting is reachable
  EXPECT_LT(speed_with_torque_dps(m, 1e-9, 19.0), 4300.0); // and not at 19 V
}

TEST(MotorModel, TorqueNearMaxSpeedAt24V_A_MOTOR_2) {
  const MotorModel m = default_module_model().drive.motor; // the model card's
  // Full peak torque up to ~4200 deg/s, half of it still at 4300 deg/s: the
  // end of the S-curve's acceleration phase needs little torque (A-MOTOR-2).
  EXPECT_NEAR(speed_with_torque_dps(m, m.peak_torque_Nm(), 24.0), 4208.0, 5.0);
  EXPECT_GT(m.max_torque_Nm(deg_to_rad(4300.0), 24.0, 1.0), 0.3);
  // manual 3.5.3: 4300 x 19 / 24 = 3404 deg/s at 19 V: 3300 deg/s still with
  // the rated torque, 3500 deg/s with none at all (no-load 3483 deg/s).
  EXPECT_GT(speed_with_torque_dps(m, kMotorTorque_Nm, 19.0), 3300.0);
  EXPECT_EQ(m.max_torque_Nm(deg_to_rad(3500.0), 19.0, 1.0), 0.0);
  EXPECT_NEAR(speed_with_torque_dps(m, 1e-9, 19.0), 4400.0 * 19.0 / 24.0, 0.01);
}

TEST(MotorModel, BrakingAlwaysHasPeakTorque) {
  const MotorModel m = default_module_model().drive.motor; // the model card's
  for (double v : {0.0, 10.0, 75.0, 200.0}) {
    EXPECT_EQ(m.max_torque_Nm(v, 19.0, -1.0), m.peak_torque_Nm());
    EXPECT_EQ(m.max_torque_Nm(-v, 19.0, 1.0), m.peak_torque_Nm());
  }
}

TEST(MotorModel, SaturateClampsPerDirection) {
  const MotorModel m = default_module_model().drive.motor; // the model card's
  EXPECT_EQ(m.saturate(5.0, 0.0, 24.0), m.peak_torque_Nm());
  EXPECT_EQ(m.saturate(-5.0, 0.0, 24.0), -m.peak_torque_Nm());
  EXPECT_EQ(m.saturate(0.1, 0.0, 24.0), 0.1);
  EXPECT_EQ(m.saturate(0.5, deg_to_rad(4600.0), 24.0), 0.0); // beyond no-load speed
  EXPECT_NEAR(m.copper_loss_W(m.peak_torque_Nm()),
              m.current_limit_A * m.current_limit_A * m.winding_resistance_ohm, 1e-12);
}

TEST(MotorModel, DefaultSetsFeasibleAt24VAcrossLoadRange) {
  // Parameter sets 1..7 default to 3000 deg/s, 100 %, 100 % (manual 6.2);
  // with the load configured right they need M plus friction at most.
  const MotorModel m = default_module_model().drive.motor; // the model card's
  for (double load = 0.0; load <= 15000.0; load += 1500.0) {
    EXPECT_GT(min_margin_Nm(m, 3000.0, load, 24.0), 0.09) << load;
    EXPECT_GT(min_margin_Nm(m, 4300.0, load, 24.0), 0.07) << load; // max setting too (A-MOTOR-2)
  }
}

TEST(MotorModel, MaxSpeedInfeasibleAt19V) {
  const MotorModel m = default_module_model().drive.motor; // the model card's
  for (double load : {0.0, 15000.0}) {
    EXPECT_LT(min_margin_Nm(m, 4300.0, load, 19.0), 0.0) << load;
    EXPECT_GT(min_margin_Nm(m, 3300.0, load, 19.0), 0.0) << load; // ~4300 x 19/24 still works
  }
}

} // namespace
} // namespace sreh
