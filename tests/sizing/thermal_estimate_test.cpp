// Times to the 70 degC warning (manual 7.3, 115.1) and to the 75 degC
// overtemperature error (manual 7.2, 114.3, the trip) under a constant mean
// loss, from the twin's own thermal model (A-SIZE-6).
#include <gtest/gtest.h>

#include "sizing/thermal_estimate.hpp"
#include "twin/thermal.hpp"

namespace sreh::sizing {
namespace {

// The card's winding-to-ambient resistance in series (A-TWIN-THERMAL-1:
// 3 + 6 K/W with the issue-35 card): 70 degC from 25 degC at 5.0 W, 75 degC
// at 5.6 W.
double series_K_per_W() {
  const ThermalConstants& t = default_module_model().thermal;
  return t.winding_to_housing_K_per_W + t.housing_to_ambient_K_per_W;
}

// The loss whose steady state lies `above_C` over ambient.
double loss_for(double above_C) { return above_C / series_K_per_W(); }

// The sensed temperature after t seconds of the loss, integrated finely.
double temperature_after(double loss_W, double ambient_C, double t_s) {
  Thermal th(ThermalSpec{ambient_C, 1.0}, default_module_model().thermal);
  const int n = static_cast<int>(t_s / 0.01);
  for (int i = 0; i < n; ++i) th.step(0.01, loss_W);
  return th.sensor_C();
}

TEST(ThermalEstimate, TripFollowsWarningWhenSteadyStateAbove75_7_2) {
  const double loss_W = loss_for(70.0); // steady 95 degC from 25 degC (7.8 W with the card)
  const ThermalEstimate e = estimate_thermal(loss_W, 25.0, default_module_model().thermal);
  EXPECT_NEAR(e.steady_C, 25.0 + loss_W * series_K_per_W(), 1e-9);
  EXPECT_NEAR(e.steady_C, 95.0, 1e-9);
  ASSERT_TRUE(e.time_to_warning_s);
  ASSERT_TRUE(e.time_to_trip_s);
  EXPECT_GT(*e.time_to_trip_s, *e.time_to_warning_s);
  // Each is where the model crosses its threshold (0.5 s steps).
  EXPECT_LT(temperature_after(loss_W, 25.0, *e.time_to_trip_s - 1.0), kTemperatureTrip_C);
  EXPECT_GT(temperature_after(loss_W, 25.0, *e.time_to_trip_s + 1.0), kTemperatureTrip_C);
  EXPECT_LT(temperature_after(loss_W, 25.0, *e.time_to_warning_s - 1.0), 70.0);
  EXPECT_GT(temperature_after(loss_W, 25.0, *e.time_to_warning_s + 1.0), 70.0);
}

TEST(ThermalEstimate, NoTripWhenTheSteadyStateStaysBelow75) {
  const ThermalEstimate warm = estimate_thermal(loss_for(47.5), 25.0, default_module_model().thermal); // steady 72.5 degC: warning only
  EXPECT_NEAR(warm.steady_C, 72.5, 1e-9);
  EXPECT_TRUE(warm.time_to_warning_s);
  EXPECT_FALSE(warm.time_to_trip_s);
  const ThermalEstimate cool = estimate_thermal(loss_for(40.0), 25.0, default_module_model().thermal); // 65 degC
  EXPECT_FALSE(cool.time_to_warning_s);
  EXPECT_FALSE(cool.time_to_trip_s);
}

TEST(ThermalEstimate, CurveRisesFromAmbientTowardsSteadyState) {
  const std::vector<TemperaturePoint> c = temperature_curve(0.5, 30.0, 600.0, 1.0, default_module_model().thermal);
  ASSERT_EQ(c.size(), 601u);
  EXPECT_EQ(c.front().C, 30.0);
  for (std::size_t i = 1; i < c.size(); ++i) EXPECT_GE(c[i].C, c[i - 1].C);
  EXPECT_LT(c.back().C, 30.0 + 0.5 * series_K_per_W());
  EXPECT_NEAR(c.back().C, temperature_after(0.5, 30.0, 600.0), 0.2);
}

} // namespace
} // namespace sreh::sizing
