// The one load-file loader (issue 13): `size --load`, the fuzz target and
// anything else read a load file here, with the scenario's own load and
// mounting keys, limits and FILE:LINE:COL errors (scenarios/README.md).
#include <gtest/gtest.h>

#include <string>

#include "scenarios/load_file.hpp"

namespace sreh {
namespace {

std::string error_of(const std::string& text) {
  try {
    (void)parse_load_text(text, "load.yaml", "");
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

TEST(LoadFile, LoadAndMountingAsInAScenario) {
  const LoadFileContents c =
      parse_load_text("name: arm\nmounting: {axis: horizontal}\nload: {arm: {mass_kg: 0.3, radius_m: 0.06}}\n",
                      "load.yaml", "");
  const auto& arm = std::get<ArmLoad>(c.load);
  EXPECT_DOUBLE_EQ(arm.mass_kg, 0.3);
  EXPECT_DOUBLE_EQ(arm.radius_m, 0.06);
  ASSERT_TRUE(c.mounting_tilt_deg.has_value());
  EXPECT_DOUBLE_EQ(*c.mounting_tilt_deg, 90.0); // horizontal = 90 deg from vertical (A-TWIN-24)
}

TEST(LoadFile, NoMountingKeyLeavesTheMountingUnset) {
  const LoadFileContents c = parse_load_text("load: {inertia_gcm2: 2500}\n", "load.yaml", "");
  EXPECT_DOUBLE_EQ(std::get<InertiaLoad>(c.load).inertia_gcm2, 2500.0);
  EXPECT_FALSE(c.mounting_tilt_deg.has_value());
}

TEST(LoadFile, AWholeScenarioIsCheckedAsOne) {
  const LoadFileContents c = parse_load_text(
      "name: s\nload: {inertia_gcm2: 100}\nmounting: {tilt_deg: 30}\nsteps:\n  - comment: x\n", "load.yaml", "");
  EXPECT_DOUBLE_EQ(std::get<InertiaLoad>(c.load).inertia_gcm2, 100.0);
  EXPECT_DOUBLE_EQ(c.mounting_tilt_deg.value_or(-1), 30.0);
  // A scenario's own errors still come with their line (its step is wrong).
  EXPECT_NE(error_of("name: s\nload: {inertia_gcm2: 100}\nsteps:\n  - wiat: 1\n").find("load.yaml:4:"),
            std::string::npos);
}

TEST(LoadFile, UnknownKeysAndBadValuesNameTheLine) {
  const std::string unknown = error_of("load: {inertia_gcm2: 100}\nsupply: {ohm: 1}\n");
  EXPECT_NE(unknown.find("load.yaml:2:"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("supply"), std::string::npos) << unknown;
  const std::string bad = error_of("name: x\n\nload: {inertia_gcm2: -5}\n");
  EXPECT_NE(bad.find("load.yaml:3:"), std::string::npos) << bad;
  EXPECT_NE(error_of("mounting: {axis: vertical}\n").find("'load:'"), std::string::npos);
  EXPECT_NE(error_of("load: {none: true}\nname: [1, 2]\n").find("load.yaml:2:"), std::string::npos);
}

} // namespace
} // namespace sreh
