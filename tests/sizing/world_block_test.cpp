// The world declared once (issue 30, A-SCN-32): a scenario and a cycle file
// read the world block with one reader, so the same block gives the same
// WorldSetup and the same bad value the same FILE:LINE:COL error.
#include <gtest/gtest.h>

#include <string>

#include "scenarios/scenario_parser.hpp"
#include "sizing/cycle.hpp"
#include "sizing/cycle_output.hpp"
#include "twin/model_card.hpp"

namespace sreh::sizing {
namespace {

// Every world key, canonical spelling; the model file is one of the project's.
const std::string kWorld =
    "model: models/sreh50-model.yaml\n"
    "device:\n"
    "  supply_V: 20\n"
    "  ambient_C: 35\n"
    "  source_resistance_ohm: 0.5\n"
    "  bus_capacitance_F: 0.002\n"
    "load: {arm: {mass_kg: 0.3, radius_m: 0.06}}\n"
    "mounting: {axis: horizontal}\n"
    "world: {hard_stops: [{angle_deg: 170}]}\n";

const std::string kSteps = "steps: [{wait_s: 0.01}]\n";
const std::string kSegments = "segments: [{move_deg: 90, speed_dps: 1000}]\n";

Scenario scenario(const std::string& world) { return parse_scenario_text("name: w\n" + world + kSteps, "w.yaml", ""); }
CycleRequest cycle(const std::string& world) { return parse_cycle_text("name: w\n" + world + kSegments, "w.yaml", ""); }

void expect_same_world(const WorldSetup& a, const WorldSetup& b) {
  EXPECT_EQ(a.load, b.load);
  EXPECT_EQ(a.load_loc.str(), b.load_loc.str());
  EXPECT_EQ(a.hard_stops, b.hard_stops);
  EXPECT_EQ(a.supply.voltage_V, b.supply.voltage_V);
  EXPECT_EQ(a.supply.source_resistance_ohm, b.supply.source_resistance_ohm);
  EXPECT_EQ(a.supply.bus_capacitance_F, b.supply.bus_capacitance_F);
  EXPECT_EQ(a.thermal.ambient_C, b.thermal.ambient_C);
  EXPECT_EQ(a.thermal.time_scale, b.thermal.time_scale);
  EXPECT_EQ(a.mounting_tilt_deg, b.mounting_tilt_deg);
  EXPECT_EQ(a.physics_dt_s, b.physics_dt_s);
  EXPECT_EQ(a.model_file, b.model_file);
  EXPECT_EQ(a.model_loc.str(), b.model_loc.str());
  EXPECT_TRUE(a.module == b.module);
}

TEST(WorldBlock, TheSameBlockGivesTheSameWorldInAScenarioAndACycle) {
  const WorldSetup s = scenario(kWorld).world;
  const WorldSetup c = cycle(kWorld).world;
  expect_same_world(s, c);
  // And the values are the file's, not the defaults.
  EXPECT_EQ(s.supply.voltage_V, 20.0);
  EXPECT_EQ(s.supply.source_resistance_ohm, 0.5);
  EXPECT_EQ(s.supply.bus_capacitance_F, 0.002);
  EXPECT_EQ(s.thermal.ambient_C, 35.0);
  EXPECT_EQ(s.mounting_tilt_deg, 90.0);
  ASSERT_EQ(s.hard_stops.size(), 1u);
  EXPECT_EQ(s.hard_stops[0].angle_deg, 170.0);
  EXPECT_NE(s.model_file.find("sreh50-model.yaml"), std::string::npos);
  EXPECT_EQ(s.load_loc.str(), "w.yaml:8:7");
}

// The cycle file's old keys (supply.*, top-level ambient_C) are aliases in both formats.
TEST(WorldBlock, CycleKeysAreAliasesInBothFormats) {
  const std::string aliases =
      "supply: {voltage_V: 20, source_resistance_ohm: 0.5, bus_capacitance_F: 0.002}\n"
      "ambient_C: 35\n";
  const std::string canonical =
      "device: {supply_V: 20, ambient_C: 35, source_resistance_ohm: 0.5, bus_capacitance_F: 0.002}\n";
  expect_same_world(scenario(aliases).world, scenario(canonical).world);
  expect_same_world(cycle(aliases).world, cycle(canonical).world);
  expect_same_world(scenario(aliases).world, cycle(canonical).world);
  EXPECT_EQ(cycle(aliases).world.supply.voltage_V, 20.0);
  EXPECT_EQ(scenario(aliases).world.thermal.ambient_C, 35.0);
}

template <class Parse>
std::string error_of(Parse parse, const std::string& world) {
  try {
    (void)parse(world);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// One range per key, one message: 2000 ohm is beyond every world (A-SCN-32).
TEST(WorldBlock, AnOutOfRangeValueGivesTheSameErrorInBoth) {
  for (const std::string& world : {std::string("device: {source_resistance_ohm: 2000}\n"),
                                   std::string("supply: {bus_capacitance_F: 11}\n"),
                                   std::string("mounting: {tilt_deg: 181}\n"),
                                   std::string("world: {hard_stops: [{angle_deg: 800}]}\n")}) {
    const std::string in_scenario = error_of(scenario, world);
    const std::string in_cycle = error_of(cycle, world);
    EXPECT_NE(in_scenario.find("w.yaml:"), std::string::npos) << world;
    EXPECT_NE(in_scenario.find("out of range"), std::string::npos) << in_scenario;
    EXPECT_EQ(in_scenario, in_cycle) << world;
  }
  EXPECT_EQ(error_of(scenario, "device: {source_resistance_ohm: 2000}\n"),
            "w.yaml:2:33: device.source_resistance_ohm: 2000 is out of range [0, 1000]");
}

// A key and its alias together: refused at the alias, in both formats.
TEST(WorldBlock, AKeyAndItsAliasTogetherAreRefused) {
  const std::string both = "device: {supply_V: 24}\nsupply: {voltage_V: 20}\n";
  const std::string in_scenario = error_of(scenario, both);
  EXPECT_NE(in_scenario.find("w.yaml:3:21: supply.voltage_V: the same as device.supply_V"), std::string::npos)
      << in_scenario;
  EXPECT_EQ(in_scenario, error_of(cycle, both));
}

// A sizing narrows the supply to the index 85 window and the ambient to
// 0 .. 50 degC (A-SIZE-1, A-SIZE-2), at the file's line; a scenario may
// run its module outside them (undervoltage, heat).
TEST(WorldBlock, ASizingNarrowsSupplyAndAmbient_6_2) {
  EXPECT_EQ(scenario("device: {supply_V: 12, ambient_C: 60}\n").world.supply.voltage_V, 12.0);
  EXPECT_EQ(error_of(cycle, "device: {supply_V: 12}\n"), "w.yaml:2:20: device.supply_V: 12 is out of range [16, 32]");
  EXPECT_EQ(error_of(cycle, "ambient_C: 60\n"), "w.yaml:2:12: ambient_C: 60 is out of range [0, 50]");
  // A scenario's own keys of `device:` are not a cycle's.
  EXPECT_NE(error_of(cycle, "device: {isdu: []}\n").find("w.yaml:2:"), std::string::npos);
}

// The cycle's whole world reaches the search of every recommended set
// (A-SIZE-20): a cycle of one move back and forth recommends what `size`
// recommends for that move, also with another model card (a weaker motor).
TEST(WorldBlock, ACyclesSetIsSearchedInTheCyclesWorld) {
  SizingRequest single;
  single.angle_deg = 90;
  single.dwell_s = 0.1;
  single.world.load = DiskLoad{0.5, 0.05};
  single.world.module = load_module_model(std::string(SREH_SOURCE_DIR) + "/tests/sizing/data/weak_motor_model.yaml");
  ASSERT_FALSE(single.world.module == default_module_model());
  const SizingResult alone = size(single);
  ASSERT_TRUE(alone.feasible) << alone.evaluation.reason;
  const CycleResult in_cycle = size_cycle(cycle_of_single(single));
  ASSERT_EQ(in_cycle.settings.size(), 1u);
  EXPECT_EQ(in_cycle.backoffs, 0);
  EXPECT_EQ(in_cycle.settings[0].speed_dps, alone.evaluation.set.setting.speed_dps);
  EXPECT_EQ(in_cycle.settings[0].accel_pct, alone.evaluation.set.setting.accel_pct);
  EXPECT_EQ(in_cycle.settings[0].jerk_pct, alone.evaluation.set.setting.jerk_pct);
}

} // namespace
} // namespace sreh::sizing
