// Figures at a stated resolution (issue 29): the unit a name carries decides
// the decimals; the written text has no float noise.
#include "io/figures.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace sreh::io {
namespace {

std::string written(std::string_view name, double v) { return fmt::format("{}", round_figure(name, v)); }

TEST(Figures, TheUnitSuffixChoosesTheResolution) {
  EXPECT_EQ(figure_decimals("positioning_s"), 6);
  EXPECT_EQ(figure_decimals("wait_ms"), 3);
  EXPECT_EQ(figure_decimals("max_tracking_error_deg"), 6);
  EXPECT_EQ(figure_decimals("peak_torque_Nm"), 6);
  EXPECT_EQ(figure_decimals("steady_temperature_C"), 4);
  EXPECT_EQ(figure_decimals("settling_s_range"), 6); // a qualifier is looked through
  EXPECT_EQ(figure_decimals("positioning_s_hi"), 6);
  EXPECT_EQ(figure_decimals("cycles_per_min"), 3);
  EXPECT_EQ(figure_decimals("torque_min"), -1); // "min" alone is not a unit here
  EXPECT_EQ(figure_decimals("min_torque_headroom"), -1); // no unit: 9 significant digits
  EXPECT_EQ(figure_decimals("value"), -1);
}

TEST(Figures, FloatNoiseIsGoneFromTheText) {
  EXPECT_EQ(written("max_tracking_error_deg", 0.044868836396915975), "0.044869");
  EXPECT_EQ(written("travel_s", 0.034121338939809016), "0.034121");
  EXPECT_EQ(written("t_s", 0.10400000000000001), "0.104");
  EXPECT_EQ(written("end_deg", 450.0013732910156), "450.001373");
  EXPECT_EQ(written("max_temperature_C", 25.058548625765187), "25.0585");
  EXPECT_EQ(written("min_torque_headroom", 0.1493709317277634), "0.149370932");
  EXPECT_EQ(written("load_gcm2", 2000.0), "2000");
}

TEST(Figures, SignOfZeroAndNonFiniteValues) {
  EXPECT_EQ(written("speed_dps", -0.0), "0");
  EXPECT_EQ(written("position_deg", -1e-9), "0");
  EXPECT_TRUE(std::isnan(round_figure("x_s", std::numeric_limits<double>::quiet_NaN())));
  EXPECT_EQ(round_figure("x_s", std::numeric_limits<double>::infinity()), std::numeric_limits<double>::infinity());
}

TEST(Figures, RoundingTwiceChangesNothing) {
  for (double v : {0.044868836396915975, 1234.56789012345, -3.0000005, 7e-7}) {
    const double once = round_figure("a_deg", v);
    EXPECT_EQ(round_figure("a_deg", once), once) << v;
  }
}

TEST(Figures, EveryFloatOfAJsonDocumentByItsKey) {
  nlohmann::json j = {{"positioning_s", 0.099659351123},
                      {"settling_s_range", {0.0251234567, 0.0309876543}},
                      {"moves", {{{"end_deg", 90.00137329101562}, {"number", 3}}}},
                      {"name", "x"},
                      {"count", 7}};
  round_figures(j);
  EXPECT_EQ(j.dump(), R"({"count":7,"moves":[{"end_deg":90.001373,"number":3}],"name":"x",)"
                      R"("positioning_s":0.099659,"settling_s_range":[0.025123,0.030988]})");
}

} // namespace
} // namespace sreh::io
