// A load change while running (A-TWIN-33, Plant::set_load / Twin::set_load):
// the plant afterwards behaves as one built with that load, keeps where the
// flange is, and refuses a load the module cannot carry without changing.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "device_logic/units.hpp"
#include "tests/twin/plant_helpers.hpp"
#include "twin/plant.hpp"

namespace sreh {
namespace {

using test::config_with;

// Motor off (bridge disabled): an external torque turns the flange.
void push(Plant& plant, double torque_Nm, int steps) {
  plant.set_external_torque(torque_Nm);
  for (int i = 0; i < steps; ++i) plant.step(MotorCommand{});
  plant.set_external_torque(0.0);
}

TEST(PlantLoad, AfterTheChangeThePlantMovesLikeOneBuiltWithTheLoad) {
  Plant changed(config_with(InertiaLoad{1000.0}));
  push(changed, 0.05, 200); // 20 ms with the light load: the flange turns
  const double angle_before = changed.angle_rad();
  const double speed_before = changed.velocity_rad_s();
  ASSERT_GT(angle_before, 0.0);
  changed.set_load(InertiaLoad{8000.0});
  EXPECT_NEAR(kgm2_to_gcm2(changed.load_inertia_kgm2()), 8000.0, 1.0);
  EXPECT_DOUBLE_EQ(changed.angle_rad(), angle_before); // the flange stays where it is
  EXPECT_DOUBLE_EQ(changed.velocity_rad_s(), speed_before);

  // Reference: built with 8000 g cm^2, put in the same state.
  Plant built(config_with(InertiaLoad{8000.0}));
  built.set_flange_angle(angle_before, speed_before);
  push(changed, 0.2, 300);
  push(built, 0.2, 300);
  EXPECT_NEAR(changed.velocity_rad_s(), built.velocity_rad_s(), 0.01 * std::abs(built.velocity_rad_s()));
  // And clearly unlike the light load.
  Plant light(config_with(InertiaLoad{1000.0}));
  light.set_flange_angle(angle_before, speed_before);
  push(light, 0.2, 300);
  EXPECT_GT(light.velocity_rad_s(), 2.0 * built.velocity_rad_s());
}

TEST(PlantLoad, RefusesALoadAboveTheLimitAndKeepsTheOld) {
  Plant plant(config_with(InertiaLoad{2000.0}));
  EXPECT_THROW(plant.set_load(InertiaLoad{20000.0}), std::invalid_argument); // manual 6.2, 64.4
  EXPECT_NEAR(kgm2_to_gcm2(plant.load_inertia_kgm2()), 2000.0, 1.0);
  push(plant, 0.05, 10); // still steps
  EXPECT_GT(plant.velocity_rad_s(), 0.0);
}

} // namespace
} // namespace sreh
