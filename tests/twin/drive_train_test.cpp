// The plant's drive train (issue 14): two masses on a torsional compliance,
// gravity from the mounting, turning the unpowered module by hand.
// docs/assumptions/twin.md A-TWIN-4, A-TWIN-20..24.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "device_logic/units.hpp"
#include "twin/plant.hpp"

namespace sreh {
namespace {

// Times of the upward zero crossings of `x` (linear interpolation), from
// samples taken every `dt_s`.
std::vector<double> upward_crossings(const std::vector<double>& x, double dt_s) {
  std::vector<double> t;
  for (std::size_t k = 1; k < x.size(); ++k) {
    if (x[k - 1] < 0.0 && x[k] >= 0.0) {
      t.push_back((static_cast<double>(k) - x[k] / (x[k] - x[k - 1])) * dt_s);
    }
  }
  return t;
}

TEST(DriveTrain, TwoMassesMakeUpJIntern_3_5_4) {
  Plant plant(PlantConfig{});
  EXPECT_NEAR(plant.rotor_inertia_kgm2() + plant.flange_inertia_kgm2(), kInternalInertia_kgm2, 1e-11);
  EXPECT_GT(plant.stiffness_Nm_per_rad(), 0.0);
}

// servo.md: the antiresonance w_a = sqrt(k / J_l) is the load swinging on
// the spring against a motor side that stands still. Motor off, the rotor
// held by its bearing friction: a small steady torque on the flange takes
// up the gear's backlash (A-TWIN-45; the flank's impact may nudge the
// rotor) and keeps the flanks touching, then a
// knock too small to break the rotor loose or to lift the flanks: the load
// rings at w_a about its preloaded twist, and the rotor (with the encoder)
// does not move.
TEST(DriveTrain, LoadRingsAtTheAntiresonanceAgainstAStillRotor) {
  for (double load_gcm2 : {5000.0, 15000.0}) {
    PlantConfig c;
    c.load = InertiaLoad{load_gcm2};
    Plant plant(c);
    const double j_l = plant.flange_inertia_kgm2();
    const double w_a = std::sqrt(plant.stiffness_Nm_per_rad() / j_l);
    const double preload_Nm = 0.006;
    plant.set_external_torque(preload_Nm);
    for (int i = 0; i < 2000; ++i) plant.step(MotorCommand{}); // 0.2 s: onto the flank, ringing decayed
    const int64_t rotor_counts = plant.sensors().encoder_counts;  // the flank's impact may have nudged it
    plant.set_external_torque(preload_Nm + 0.003);              // knock: 0.5 ms
    for (int i = 0; i < 5; ++i) plant.step(MotorCommand{});
    plant.set_external_torque(preload_Nm);
    std::vector<double> twist;
    for (int i = 0; i < 1000; ++i) { // 0.1 s
      plant.step(MotorCommand{});
      twist.push_back(plant.twist_rad());
    }
    EXPECT_EQ(plant.sensors().encoder_counts, rotor_counts) << load_gcm2;
    double mean = 0;
    for (double x : twist) mean += x / static_cast<double>(twist.size());
    for (double& x : twist) x -= mean;
    const std::vector<double> t = upward_crossings(twist, plant.physics_dt_s());
    ASSERT_GE(t.size(), 3u) << load_gcm2;
    const double period_s = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
    const double w = 2.0 * kPi / period_s;
    EXPECT_NEAR(w, w_a, 0.1 * w_a) << load_gcm2 << " g cm^2: " << w / (2 * kPi) << " Hz vs " << w_a / (2 * kPi);
  }
}

// A horizontal axis with an eccentric mass m at radius r needs
// m g r cos(angle) of holding torque (servo.md "Gravity"); the arm points
// along +x at flange angle 0 (A-TWIN-24).
TEST(DriveTrain, HorizontalAxisGravityTorqueFollowsMgrCosAngle) {
  const double m = 0.2, r = 0.06;
  for (double tilt : {90.0, 30.0}) {
    PlantConfig c;
    c.load = ArmLoad{m, r, 0.0};
    c.mounting_tilt_deg = tilt;
    Plant plant(c);
    for (double deg : {0.0, 30.0, 60.0, 90.0, 135.0, -45.0}) {
      plant.set_flange_angle(deg_to_rad(deg));
      const double expected = m * 9.81 * r * std::sin(deg_to_rad(tilt)) * std::cos(deg_to_rad(deg));
      EXPECT_NEAR(plant.gravity_torque_Nm(), expected, 1e-9) << tilt << " deg tilt, " << deg << " deg";
    }
  }
  // A vertical axis (the default) or a load on the axis: no gravity torque.
  PlantConfig vertical;
  vertical.load = ArmLoad{m, r, 0.0};
  Plant plant(vertical);
  plant.set_flange_angle(0.3);
  EXPECT_NEAR(plant.gravity_torque_Nm(), 0.0, 1e-12);
}

TEST(DriveTrain, MountingTiltOutOfRangeIsRefused) {
  PlantConfig c;
  c.mounting_tilt_deg = 200.0;
  EXPECT_THROW(Plant{c}, std::invalid_argument);
}

// For turning the unpowered module by hand: rotor and flange go there at
// rest, the encoder follows.
TEST(DriveTrain, TurnToMovesRotorAndFlangeAndEncoder) {
  Plant plant(PlantConfig{});
  plant.set_flange_angle(deg_to_rad(123.0));
  EXPECT_NEAR(rad_to_deg(plant.angle_rad()), 123.0, 1e-12);
  EXPECT_NEAR(rad_to_deg(plant.rotor_angle_rad()), 123.0, 1e-12);
  EXPECT_EQ(plant.sensors().encoder_counts, rad_to_internal_counts(deg_to_rad(123.0)));
  plant.step(MotorCommand{});
  EXPECT_NEAR(rad_to_deg(plant.angle_rad()), 123.0, 1e-6);
}

} // namespace
} // namespace sreh
