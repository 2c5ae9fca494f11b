// The load as a fitted quantity of the setup (issue 36, A-CAL-14): what a
// factor does to a load, how the logs share it, and that the replay keeps
// the sets configured for the stated load. Cheap checks; the fit itself is
// CalibrationCases.AFivePercentLoadErrorIsRecoveredWithFitLoad.
#include <gtest/gtest.h>

#include "calibration/fit_cost.hpp"
#include "calibration/load_scale.hpp"
#include "calibration_rig.hpp"
#include "device_logic/parameter_table.hpp"
#include "device_logic/units.hpp"
#include "twin/load_builder.hpp"

namespace sreh {
namespace {

double axis_gcm2(const LoadSpec& load) { return kgm2_to_gcm2(built_load_inertia_kgm2(load, {}, 1e-4)); }

FitCase case_with(const LoadSpec& load, const std::string& path) {
  FitCase c;
  c.log.path = path;
  c.setup.config.load = load;
  return c;
}

// Every mass times the factor, shape and place kept: the inertia about the
// axis, parallel-axis terms included, scales by exactly the factor.
TEST(FitLoad, AFactorScalesTheInertiaAboutTheAxis) {
  const LoadPart off_axis{BoxLoad{0.2, 0.06, 0.03, 0.02}, {0.05, 0.01, 0.02}, {0, 0, 30}, "", "box"};
  const LoadPart point{PointPart{0.1}, {-0.04, 0, 0.03}, {}, "", "screw"};
  const LoadSpec assembly = AssemblyLoad{{off_axis, point}, ""};
  for (const LoadSpec& load : {LoadSpec{InertiaLoad{5000}}, LoadSpec{DiskLoad{0.3, 0.06}}, LoadSpec{ArmLoad{0.05, 0.1, 0.02}},
                               assembly}) {
    const double stated = axis_gcm2(load);
    for (const double f : {0.8, 1.05, 1.25}) {
      EXPECT_NEAR(axis_gcm2(scaled_load(load, f)), f * stated, 1e-6 * stated) << describe_load(load) << " x " << f;
    }
  }
  EXPECT_EQ(why_not_scalable(assembly), "");
  EXPECT_NE(why_not_scalable(MjcfLoad{"gripper.xml"}), "");
  EXPECT_THROW(scaled_load(MjcfLoad{"gripper.xml"}, 1.05), CalibrationInputError);
}

// One factor per stated load, shared by the logs that state it; a log
// without a load has none; the factor never asks the twin for more than
// the module may carry.
TEST(FitLoad, OneFactorPerStatedLoad) {
  const ModelCard card = default_model_card();
  const Unknowns same = unknowns_of(card, {"coulomb_friction", "load"},
                                    {case_with(InertiaLoad{5000}, "a.csv"), case_with(InertiaLoad{5000}, "b.csv")});
  ASSERT_EQ(same.card_index.size(), 2u);
  EXPECT_TRUE(same.is_load(1));
  EXPECT_EQ(same.load_name[1], "load_inertia");
  EXPECT_EQ(same.case_load, (std::vector<std::ptrdiff_t>{1, 1}));
  EXPECT_NEAR(same.scale[1], 5000, 0.5);
  EXPECT_DOUBLE_EQ(same.lo[1], kLoadScaleLo);
  EXPECT_DOUBLE_EQ(same.hi[1], kLoadScaleHi);

  const Unknowns two = unknowns_of(card, {"load_inertia"}, {case_with(NoLoad{}, "none.csv"), case_with(InertiaLoad{5000}, "a.csv"),
                                                            case_with(InertiaLoad{15000}, "heavy.csv")});
  ASSERT_EQ(two.card_index.size(), 2u);
  EXPECT_EQ(two.case_load, (std::vector<std::ptrdiff_t>{-1, 0, 1}));
  EXPECT_EQ(two.load_name[0], "load_inertia (a.csv)");
  EXPECT_EQ(two.load_name[1], "load_inertia (heavy.csv)");
  EXPECT_NEAR(two.hi[1], 1.0, 1e-6); // 15000 g cm^2 stated: the module's maximum already
  const FitPoint p = point_at(card, two, std::vector<double>{1.1, 0.9}.data(), 3);
  EXPECT_EQ(p.load_scale, (std::vector<double>{1.0, 1.1, 0.9}));

  EXPECT_THROW(unknowns_of(card, {"load"}, {case_with(NoLoad{}, "none.csv")}), CalibrationInputError);
  EXPECT_THROW(unknowns_of(card, {"load"}, {case_with(MjcfLoad{"gripper.xml"}, "a.csv")}), CalibrationInputError);
  EXPECT_THROW(unknowns_of(card, {"load", "load_inertia"}, {case_with(InertiaLoad{5000}, "a.csv")}), CalibrationInputError);
}

// A replay with the load scaled is the module carrying the scaled load on
// sets still configured for the stated one: the same track as a setup that
// says so outright.
TEST(FitLoad, TheSetsStayConfiguredForTheStatedLoad) {
  const Scenario plan = test::plan_moves(5000, {0, 1});
  Scenario heavier = plan;
  heavier.world.load = InertiaLoad{5250};
  const MasterLog log = test::record_log(heavier, default_model_card());
  const ModuleModel module = default_model_card().module_model();

  ReplaySetup scaled = replay_setup(log, InertiaLoad{5000}, &plan);
  scaled.load_scale = 1.05;
  const ReplaySetup carried = replay_setup(log, InertiaLoad{5250}, &plan); // the plan's writes: sets for 5000
  const ReplayTrack a = replay(scaled, module, log);
  EXPECT_EQ(a.position_deg, replay(carried, module, log).position_deg);
  EXPECT_NE(a.position_deg, replay(replay_setup(log, InertiaLoad{5000}, &plan), module, log).position_deg);

  // Without a setup scenario the replay configures every set from the
  // load: the stated one, not the scaled one.
  ReplaySetup bare = replay_setup(log, InertiaLoad{5000}, nullptr);
  bare.load_scale = 1.05;
  ReplaySetup by_writes = replay_setup(log, InertiaLoad{5250}, nullptr); // 5250 carried, every set told 5000
  by_writes.configure_load = false;
  for (uint16_t index = 64; index <= 71; ++index) {
    IsduWriteStep w;
    w.index = index;
    w.subindex = 4;
    w.data = encode_number(ParamType::UInt16, 5000);
    by_writes.startup_writes.push_back(w);
  }
  EXPECT_EQ(replay(bare, module, log).position_deg, replay(by_writes, module, log).position_deg);
}

} // namespace
} // namespace sreh
