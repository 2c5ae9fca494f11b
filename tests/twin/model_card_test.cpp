// Issue 25: the model card (models/sreh50-model.yaml, twin/model_card.hpp).
// Every constant with value, unit, source and range; a model file overrides
// any subset; bad files are refused naming file:line and the constant.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "device_logic/units.hpp"
#include "twin/model_card.hpp"
#include "twin/twin.hpp"

namespace sreh {
namespace {

struct TempFile {
  explicit TempFile(const std::string& text) {
    path = (std::filesystem::temp_directory_path() /
            ("sreh_model_" + std::to_string(::getpid()) + "_" +
             std::to_string(counter++) + ".yaml"))
               .string();
    std::ofstream(path) << text;
  }
  ~TempFile() { std::filesystem::remove(path); }
  std::string path;
  static inline int counter = 0;
};

std::string card_error_of(const std::string& text) {
  TempFile f(text);
  try {
    apply_model_file(default_model_card(), f.path);
  } catch (const ModelCardError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(f.path + ":", 0), 0u) << what; // names the file first
    return what.substr(f.path.size());
  }
  ADD_FAILURE() << "accepted: " << text;
  return {};
}

TEST(ModelCard, EveryConstantHasValueUnitSourceAndARangeHoldingIt) {
  const ModelCard& card = default_model_card();
  EXPECT_GE(card.constants.size(), 29u);
  for (const ModelConstant& c : card.constants) {
    EXPECT_FALSE(c.unit.empty()) << c.name;
    EXPECT_FALSE(c.source.empty()) << c.name;
    EXPECT_LE(c.range_lo, c.value) << c.name;
    EXPECT_LE(c.value, c.range_hi) << c.name;
  }
  // The ones issue 25 names.
  for (const char* name : {"torsional_stiffness", "torsional_damping", "coulomb_friction", "stribeck_excess",
                           "cogging_torque", "winding_resistance", "winding_inductance", "torque_constant",
                           "current_limit", "winding_to_housing_resistance", "winding_heat_capacity", "loop_delay",
                           "velocity_bandwidth", "current_loop_bandwidth", "control_period"}) {
    EXPECT_NE(card.find(name), nullptr) << name;
  }
}

TEST(ModelCard, TheCardSetsTheTwinsStructs) {
  const ModuleModel& m = default_module_model();
  EXPECT_EQ(m.drive.control_period_ns, 100'000); // 0.1 ms (A-CTRL-8)
  EXPECT_EQ(m.drive.gains.delay_periods, 3);    // A-CTRL-7
  EXPECT_DOUBLE_EQ(m.mechanics.torsional_stiffness_Nm_per_rad, default_model_card().find("torsional_stiffness")->value);
  EXPECT_NEAR(m.drive.motor.peak_torque_Nm(), 0.60, 1e-12); // A-MOTOR-3
  EXPECT_LT(m.mechanics.rotor_inertia_kgm2, kInternalInertia_kgm2); // the flange takes the rest (manual 3.5.4)
}

TEST(ModelCard, AFileOverridesASubsetAndKeepsTheRest) {
  TempFile f("constants:\n  coulomb_friction: 0.006\n  torsional_stiffness: {value: 2900, source: \"measured\"}\n");
  const ModelCard card = apply_model_file(default_model_card(), f.path);
  EXPECT_DOUBLE_EQ(card.find("coulomb_friction")->value, 0.006);
  EXPECT_DOUBLE_EQ(card.find("torsional_stiffness")->value, 2900);
  EXPECT_EQ(card.find("torsional_stiffness")->source, "measured");
  EXPECT_EQ(card.find("torsional_stiffness")->unit, "N m/rad");
  EXPECT_EQ(card.find("winding_resistance")->value, default_model_card().find("winding_resistance")->value);
  EXPECT_DOUBLE_EQ(card.module_model().mechanics.coulomb_friction_Nm, 0.006);
}

TEST(ModelCard, ARangeGivenWithTheValueLetsAModuleLieOutside) {
  TempFile f("constants:\n  coulomb_friction: {value: 0.03, range: [0.02, 0.04]}\n");
  EXPECT_DOUBLE_EQ(apply_model_file(default_model_card(), f.path).find("coulomb_friction")->range_hi, 0.04);
}

TEST(ModelCard, BadFilesNameFileLineAndConstant) {
  EXPECT_EQ(card_error_of("constants:\n  coulomb_frition: 0.01\n").substr(0, 40), ":2:3: unknown constant 'coulomb_frition'");
  EXPECT_NE(card_error_of("constants:\n  coulomb_friction: 0.1\n").find(":2:21: coulomb_friction = 0.1 N m is outside its range"),
            std::string::npos);
  EXPECT_NE(card_error_of("constants:\n  coulomb_friction: {value: 0.004, unit: \"mN m\"}\n").find("unit 'mN m' differs"),
            std::string::npos);
  EXPECT_NE(card_error_of("constants:\n  coulomb_friction: {value: 0.004, range: [0.01, 0.001]}\n").find("lo 0.01 > hi 0.001"),
            std::string::npos);
  EXPECT_NE(card_error_of("constants:\n  loop_delay: 2.5\n").find("whole number"), std::string::npos);
  EXPECT_NE(card_error_of("constants:\n  loop_delay: {value: 6, range: [0, 10]}\n").find("at most 4 control periods"),
            std::string::npos);
  EXPECT_NE(card_error_of("constants:\n  gear_efficiency: {value: 1.1, range: [0.9, 1.2]}\n").find("gear_efficiency must be at most 1"),
            std::string::npos);
  EXPECT_NE(card_error_of("constants:\n  coulomb_friction: abc\n").find("finite number, got 'abc'"), std::string::npos);
  EXPECT_NE(card_error_of("constants:\n  coulomb_friction: .nan\n").find("finite number"), std::string::npos);
  EXPECT_NE(card_error_of("constants:\n  coulomb_friction: 0.006\n  coulomb_friction: 0.007\n").find("given twice"),
            std::string::npos);
  EXPECT_NE(card_error_of("constant:\n  coulomb_friction: 0.004\n").find("unknown key 'constant'"), std::string::npos);
  EXPECT_NE(card_error_of("constants: [1, 2]\n").find("'constants' must be a mapping"), std::string::npos);
  EXPECT_NE(card_error_of("constants: {}\n---\nconstants: {}\n").find("exactly one YAML document"), std::string::npos);
  EXPECT_NE(card_error_of("constants:\n  coulomb_friction: {value: 0.004, color: red}\n").find("unknown key 'color'"),
            std::string::npos);
}

TEST(ModelCard, TheYamlItPrintsReadsBackAsTheSameCard) {
  TempFile f(model_card_yaml(default_model_card()));
  EXPECT_EQ(read_model_card(f.path), default_model_card());
  EXPECT_EQ(apply_model_file(default_model_card(), f.path), default_model_card());
}

TEST(ModelCard, ShortestNumbersReadBackExactly) {
  for (double v : {0.004, 1e-5, 6283.185307179586, 0.31252243370772176, 340.0}) {
    EXPECT_EQ(std::stod(shortest_number(v)), v);
  }
}

// Issue 25: the physics sub-steps the drive's control period; a step that
// does not divide it is refused before anything is built.
TEST(ModelCard, APhysicsStepMustDivideTheControlPeriod) {
  TwinConfig c;
  c.physics_dt_s = 0.3e-4;
  try {
    Twin twin(c);
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("must divide the drive's control period"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace sreh
