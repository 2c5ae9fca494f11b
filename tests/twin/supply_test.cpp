// Supply (issue 5, manual 6.4 index 113, 7.2 error 114.4): sag under load
// through a source resistance; regeneration charges the bus capacitor.
#include <gtest/gtest.h>

#include <cmath>

#include "device_logic/units.hpp"
#include "twin/plant.hpp"
#include "twin/supply.hpp"

namespace sreh {
namespace {

TEST(Supply, IdealSourceHoldsItsVoltage) {
  Supply s(SupplySpec{}, default_module_model().supply);
  s.step(1e-4, 50.0);
  EXPECT_EQ(s.bus_voltage_V(), 24.0);
  s.step(1e-4, -50.0);
  EXPECT_EQ(s.bus_voltage_V(), 24.0);
  s.set_source_voltage(17.0);
  EXPECT_EQ(s.bus_voltage_V(), 17.0);
}

TEST(Supply, SourceResistanceSagsUnderLoad) {
  Supply s(SupplySpec{24.0, 0.5, 0.0}, default_module_model().supply);
  s.step(1e-4, 20.0);
  const double u = s.bus_voltage_V();
  EXPECT_LT(u, 24.0);
  EXPECT_NEAR(u, 24.0 - 0.5 * 20.0 / u, 1e-9); // U = Us - R P / U
}

TEST(Supply, BusCapacitorSagsThenRecovers) {
  Supply s(SupplySpec{24.0, 0.5, 1e-3}, default_module_model().supply);
  for (int i = 0; i < 1000; ++i) s.step(1e-4, 30.0);
  EXPECT_LT(s.bus_voltage_V(), 23.5);
  for (int i = 0; i < 1000; ++i) s.step(1e-4, 0.0);
  EXPECT_NEAR(s.bus_voltage_V(), 24.0, 0.05); // bleed current drops a little over R
}

TEST(Supply, RegenerationChargesTheCapacitorAboveTheSource) {
  Supply s(SupplySpec{24.0, 0.5, 1e-3}, default_module_model().supply);
  for (int i = 0; i < 100; ++i) s.step(1e-4, -20.0); // 0.2 J back into the bus
  EXPECT_GT(s.bus_voltage_V(), 24.0);
  EXPECT_EQ(s.source_current_A(), 0.0); // a power supply cannot sink current
  // Energy balance: 1/2 C (U^2 - Us^2) = E minus the bleed.
  EXPECT_NEAR(0.5 * 1e-3 * (s.bus_voltage_V() * s.bus_voltage_V() - 24.0 * 24.0), 0.2, 0.01);
}

// Braking a large inertia without a chopper over-voltages the bus (manual 7.2,
// error 114.4.2 advice): the plant feeds motor power into the supply.
TEST(Supply, BrakingLargeInertiaRaisesBusVoltage_7_2) {
  PlantConfig c;
  c.load = InertiaLoad{15000};
  c.supply = SupplySpec{24.0, 0.5, 1e-3};
  Plant plant(c);
  double min_V = 24.0;
  for (int i = 0; i < 3000; ++i) { // accelerate 0.3 s: the bus sags
    plant.step(MotorCommand{0.485, true});
    min_V = std::min(min_V, plant.sensors().supply_V);
  }
  EXPECT_LT(min_V, 23.9);
  const double v0 = plant.velocity_rad_s();
  EXPECT_GT(v0, 50.0);
  double max_V = 0.0;
  while (plant.velocity_rad_s() > 0.0) { // full braking torque
    plant.step(MotorCommand{-0.6, true});
    max_V = std::max(max_V, plant.sensors().supply_V);
  }
  EXPECT_GT(max_V, 30.0); // above the default upper limit of index 85.2
  EXPECT_LT(plant.electrical_power_W(), 1e3);
}

TEST(Supply, PlantReportsTheBusVoltageToTheDevice) {
  PlantConfig c;
  c.supply = SupplySpec{24.0, 1.0, 0.0};
  Plant plant(c);
  plant.step(MotorCommand{0.485, true});
  EXPECT_LT(plant.sensors().supply_V, 24.0);
  plant.set_supply_voltage(17.0);
  plant.step(MotorCommand{});
  EXPECT_NEAR(plant.sensors().supply_V, 17.0, 1e-6);
}

} // namespace
} // namespace sreh
