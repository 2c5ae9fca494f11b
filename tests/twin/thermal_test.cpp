// Thermal model (issue 5; manual 6.4 index 112, warning 115.1 >= 70 degC,
// error 114.3 >= 75 degC).
#include <gtest/gtest.h>

#include "twin/thermal.hpp"

namespace sreh {
namespace {

TEST(Thermal, StartsAtAmbient) {
  Thermal t(ThermalSpec{31.0, 1.0}, default_module_model().thermal);
  EXPECT_EQ(t.sensor_C(), 31.0);
  EXPECT_EQ(t.housing_C(), 31.0);
}

TEST(Thermal, RisesWithLossAndSettlesAtAmbientPlusPRth) {
  Thermal t(ThermalSpec{25.0, 1.0}, default_module_model().thermal);
  const double loss_W = 1.0;
  double prev = t.sensor_C();
  for (int i = 0; i < 200; ++i) {
    t.step(1.0, loss_W);
    EXPECT_GT(t.sensor_C(), prev);
    prev = t.sensor_C();
  }
  for (int i = 0; i < 40000; ++i) t.step(1.0, loss_W);
  const ThermalConstants& k = t.constants();
  EXPECT_NEAR(t.winding_C(), 25.0 + loss_W * (k.winding_to_housing_K_per_W + k.housing_to_ambient_K_per_W), 1e-6);
  EXPECT_NEAR(t.housing_C(), 25.0 + loss_W * k.housing_to_ambient_K_per_W, 1e-6);
  EXPECT_NEAR(t.winding_C(), t.steady_winding_C(loss_W), 1e-6);
}

TEST(Thermal, CoolsBackToAmbient) {
  Thermal t(ThermalSpec{25.0, 1.0}, default_module_model().thermal);
  for (int i = 0; i < 600; ++i) t.step(1.0, 1.0);
  EXPECT_GT(t.sensor_C(), 50.0);
  for (int i = 0; i < 40000; ++i) t.step(1.0, 0.0);
  EXPECT_NEAR(t.sensor_C(), 25.0, 1e-6);
}

TEST(Thermal, TimeScaleMultipliesRates) {
  Thermal slow(ThermalSpec{25.0, 1.0}, default_module_model().thermal);
  Thermal fast(ThermalSpec{25.0, 100.0}, default_module_model().thermal);
  for (int i = 0; i < 100; ++i) slow.step(1.0, 10.0);
  for (int i = 0; i < 100; ++i) fast.step(0.01, 10.0);
  EXPECT_NEAR(fast.sensor_C(), slow.sensor_C(), 1e-9);
}

// A-TWIN-THERMAL: heavy fast cycling (~1.2 W: copper 1.06 W measured for
// 180 deg moves with 15000 g cm^2 and no dwell, plus speed loss) crosses 70
// and 75 degC within minutes; normal duty (~0.15 W) stays far below.
TEST(Thermal, HeavyDutyWarnsAndTripsInMinutesNormalDutyDoesNot) {
  Thermal heavy(ThermalSpec{25.0, 1.0}, default_module_model().thermal);
  int warn_s = -1, error_s = -1;
  for (int s = 1; s <= 1800; ++s) {
    heavy.step(1.0, 1.2);
    if (warn_s < 0 && heavy.sensor_C() >= 70.0) warn_s = s;
    if (error_s < 0 && heavy.sensor_C() >= 75.0) error_s = s;
  }
  EXPECT_GT(warn_s, 60);
  EXPECT_LT(warn_s, 600);
  EXPECT_GT(error_s, warn_s);
  EXPECT_LT(error_s, 900);
  Thermal normal(ThermalSpec{25.0, 1.0}, default_module_model().thermal);
  EXPECT_LT(normal.steady_winding_C(0.15), 40.0);
}

} // namespace
} // namespace sreh
