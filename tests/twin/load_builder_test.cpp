// Loads (issue 5): each family's inertia about the axis as MuJoCo computes it
// (qM minus armature, mujoco.md) against the hand formula; refusals.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "device_logic/units.hpp"
#include "twin/load_builder.hpp"

namespace sreh {
namespace {

double load_gcm2(const LoadSpec& load) {
  return kgm2_to_gcm2(build_model(load, {}, 1e-4).load_inertia_kgm2);
}

std::string builder_refusal(const LoadSpec& load) {
  try {
    build_model(load, {}, 1e-4);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(accepted)";
}

const std::string kBuilderData = std::string(SREH_SOURCE_DIR) + "/tests/twin/data/";

TEST(LoadBuilder, ModuleAloneHasJIntern_3_5_4) {
  // A-TWIN-4: rotor J_m (armature of joint "rotor") + flange J_f = J_intern.
  BuiltModel built = build_model(NoLoad{}, {}, 1e-4);
  const int rotor = mj_name2id(built.model.get(), mjOBJ_JOINT, "rotor");
  ASSERT_GE(rotor, 0);
  EXPECT_DOUBLE_EQ(built.model->dof_armature[built.model->jnt_dofadr[rotor]], 1.0e-4);
  EXPECT_NEAR(built.axis_inertia_kgm2, kInternalInertia_kgm2, 1e-11);
  EXPECT_LT(std::abs(kgm2_to_gcm2(built.load_inertia_kgm2)), 1e-4); // no load
  EXPECT_EQ(built.model->opt.timestep, 1e-4);
}

TEST(LoadBuilder, DiskIsHalfMR2) {
  EXPECT_NEAR(load_gcm2(DiskLoad{0.3, 0.08, 0.01}), kgm2_to_gcm2(0.5 * 0.3 * 0.08 * 0.08), 1e-6);
}

TEST(LoadBuilder, RingIsHalfMTimesSumOfSquares) {
  EXPECT_NEAR(load_gcm2(RingLoad{0.5, 0.04, 0.06, 0.012}), kgm2_to_gcm2(0.5 * 0.5 * (0.04 * 0.04 + 0.06 * 0.06)), 1e-6);
}

TEST(LoadBuilder, BoxIsMTimesX2PlusY2Over12) {
  EXPECT_NEAR(load_gcm2(BoxLoad{1.0, 0.1, 0.05, 0.02}), kgm2_to_gcm2(1.0 * (0.01 + 0.0025) / 12), 1e-6);
}

TEST(LoadBuilder, ArmIsPointMassPlusRodAboutItsEnd) {
  const double expected = 0.05 * 0.15 * 0.15 + 0.03 * 0.15 * 0.15 / 3;
  EXPECT_NEAR(load_gcm2(ArmLoad{0.05, 0.15, 0.03}), kgm2_to_gcm2(expected), 1e-4);
  EXPECT_NEAR(load_gcm2(ArmLoad{0.05, 0.15, 0.0}), kgm2_to_gcm2(0.05 * 0.15 * 0.15), 1e-4);
}

TEST(LoadBuilder, GivenInertiaIsReproduced_3_5_6) {
  EXPECT_NEAR(load_gcm2(InertiaLoad{5000}), 5000, 1e-6);
  EXPECT_NEAR(load_gcm2(InertiaLoad{15000}), 15000, 1e-6); // the limit itself is accepted
  EXPECT_LT(load_gcm2(InertiaLoad{0}), 1e-4);
}

// Box of full sizes (x, y) centred at distance d from the axis.
double box_z(double m, double x, double y, double d) { return m * (x * x + y * y) / 12 + m * d * d; }

TEST(LoadBuilder, ShippedGripperMatchesItsParts) {
  const double expected = 0.045 * 0.028 * 0.028 / 2 + box_z(0.220, 0.064, 0.032, 0) + box_z(0.020, 0.068, 0.020, 0) +
                          2 * box_z(0.022, 0.008, 0.016, 0.012);
  EXPECT_NEAR(load_gcm2(MjcfLoad{std::string(SREH_SOURCE_DIR "/models") + "/loads/gripper.xml"}), kgm2_to_gcm2(expected), 1e-6);
}

TEST(LoadBuilder, ShippedAsymmetricArmMatchesItsParts) {
  const double expected = 0.040 * 0.020 * 0.020 / 2 + box_z(0.060, 0.140, 0.016, 0.070) +
                          box_z(0.020, 0.024, 0.020, 0.022) + box_z(0.050, 0.024, 0.024, 0.130);
  EXPECT_NEAR(load_gcm2(MjcfLoad{std::string(SREH_SOURCE_DIR "/models") + "/loads/asymmetric_arm.xml"}), kgm2_to_gcm2(expected), 1e-6);
}

TEST(LoadBuilder, RelativeLoadPathResolvesInTheSourceTree) {
  EXPECT_GT(load_gcm2(MjcfLoad{"models/loads/gripper.xml"}), 100.0);
}

TEST(LoadBuilder, RefusesLoadAboveModuleLimit_6_2_64_4) {
  const std::string msg = builder_refusal(InertiaLoad{20000});
  EXPECT_NE(msg.find("20000"), std::string::npos) << msg;
  EXPECT_NE(msg.find("15000"), std::string::npos) << msg;
  // A disk computed by MuJoCo beyond the limit: 0.5 * 0.4 * 0.1^2 = 20000 g cm^2.
  EXPECT_NE(builder_refusal(DiskLoad{0.4, 0.1, 0.01}).find("above the module's limit"), std::string::npos);
}

TEST(LoadBuilder, RefusesNonPositiveDimensionsNamingTheField) {
  EXPECT_NE(builder_refusal(DiskLoad{0.3, 0.0, 0.01}).find("radius_m"), std::string::npos);
  EXPECT_NE(builder_refusal(DiskLoad{-1.0, 0.05, 0.01}).find("mass_kg"), std::string::npos);
  EXPECT_NE(builder_refusal(BoxLoad{1.0, 0.1, -0.1, 0.1}).find("y_m"), std::string::npos);
  EXPECT_NE(builder_refusal(RingLoad{0.5, 0.06, 0.04, 0.01}).find("inner_radius_m"), std::string::npos);
  EXPECT_NE(builder_refusal(ArmLoad{0.1, 0.1, -0.01}).find("arm_mass_kg"), std::string::npos);
  EXPECT_NE(builder_refusal(InertiaLoad{-5}).find("inertia_gcm2"), std::string::npos);
}

TEST(LoadBuilder, RefusesBrokenMjcfNamingFileAndLine) {
  const std::string file = kBuilderData + "broken_load.xml";
  const std::string msg = builder_refusal(MjcfLoad{file});
  EXPECT_NE(msg.find(file), std::string::npos) << msg;
  EXPECT_NE(msg.find("colour"), std::string::npos) << msg;
  EXPECT_NE(msg.find("line 3"), std::string::npos) << msg;
}

TEST(LoadBuilder, RefusesMalformedXmlNamingTheFile) {
  const std::string file = kBuilderData + "unclosed_load.xml";
  const std::string msg = builder_refusal(MjcfLoad{file});
  EXPECT_NE(msg.find(file), std::string::npos) << msg;
  EXPECT_NE(msg.find("invalid MJCF"), std::string::npos) << msg;
}

TEST(LoadBuilder, RefusesMissingFile) {
  const std::string msg = builder_refusal(MjcfLoad{kBuilderData + "no_such_load.xml"});
  EXPECT_NE(msg.find("no_such_load.xml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("cannot open"), std::string::npos) << msg;
}

TEST(LoadBuilder, RefusesLoadWithJoints) {
  const std::string msg = builder_refusal(MjcfLoad{kBuilderData + "jointed_load.xml"});
  EXPECT_NE(msg.find("rigid"), std::string::npos) << msg;
}

TEST(LoadBuilder, ComposedXmlIsDeterministic) {
  const LoadSpec load = RingLoad{0.5, 0.04, 0.06, 0.012};
  EXPECT_EQ(compose_model_xml(load, {HardStop{30}}), compose_model_xml(load, {HardStop{30}}));
}

} // namespace
} // namespace sreh
