// Assembly loads (issue 28): parts with offsets and turns, STL meshes,
// user MJCF in its own namespace, the limit's tolerance, each part's share.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "device_logic/units.hpp"
#include "twin/load_builder.hpp"
#include "twin/load_figures.hpp"
#include "twin/mjcf_namespace.hpp"

namespace sreh {
namespace {

const std::string kData = std::string(SREH_SOURCE_DIR) + "/tests/twin/data/";

LoadPart part(PartShape s, std::array<double, 3> at = {}, std::array<double, 3> rpy = {}) {
  return LoadPart{std::move(s), at, rpy, "", ""};
}

double gcm2(const LoadSpec& load) { return kgm2_to_gcm2(build_model(load, {}, 1e-4).load_inertia_kgm2); }

std::string refusal(const LoadSpec& load) {
  try {
    build_model(load, {}, 1e-4);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(LoadAssembly, DiskOnAxisPlusCubeAt60mm_ParallelAxis) {
  const AssemblyLoad a{{part(DiskLoad{0.5, 0.04, 0.01}, {0, 0, 0.005}), part(BoxLoad{0.2, 0.02, 0.02, 0.02}, {0.06, 0, 0.02})}, ""};
  EXPECT_NEAR(gcm2(a), 11333.3, 11333.3 * 1e-3);
  const LoadFigures f = load_figures(a);
  EXPECT_NEAR(f.mass_kg, 0.7, 1e-12);
  ASSERT_EQ(f.parts.size(), 2u);
  EXPECT_NEAR(kgm2_to_gcm2(f.parts[0].inertia_kgm2), 4000.0, 1e-6);
  EXPECT_NEAR(kgm2_to_gcm2(f.parts[1].inertia_kgm2), 7333.333, 1e-3);
  EXPECT_NEAR(f.parts[0].inertia_kgm2 + f.parts[1].inertia_kgm2, f.inertia_kgm2, 1e-12); // the parts add up to qM's figure
  EXPECT_NEAR(f.com_m[0], 0.2 * 0.06 / 0.7, 1e-12);
  EXPECT_NEAR(f.com_m[2], (0.5 * 0.005 + 0.2 * 0.02) / 0.7, 1e-12);
  EXPECT_NEAR(gravity_torque_max_Nm(f, 90), 0.7 * 9.81 * 0.2 * 0.06 / 0.7, 1e-9);
  EXPECT_EQ(gravity_torque_max_Nm(f, 0), 0.0);
}

TEST(LoadAssembly, RollTurnsABoxAboutX) {
  // Roll 90 deg: the box's z side lies along y, so Izz = m (x^2 + z^2) / 12.
  const AssemblyLoad a{{part(BoxLoad{1.0, 0.1, 0.02, 0.04}, {0, 0, 0.05}, {90, 0, 0})}, ""};
  EXPECT_NEAR(gcm2(a), kgm2_to_gcm2(1.0 * (0.01 + 0.0016) / 12), 1e-6);
  // Yaw leaves Izz alone.
  const AssemblyLoad y{{part(BoxLoad{1.0, 0.1, 0.02, 0.04}, {0, 0, 0.05}, {0, 0, 37})}, ""};
  EXPECT_NEAR(gcm2(y), kgm2_to_gcm2(1.0 * (0.01 + 0.0004) / 12), 1e-6);
}

TEST(LoadAssembly, CylinderSpherePoint) {
  EXPECT_NEAR(gcm2(AssemblyLoad{{part(CylinderPart{0.3, 0.02, 0.05}, {0, 0, 0.025})}, ""}), kgm2_to_gcm2(0.3 * 0.0004 / 2), 1e-6);
  EXPECT_NEAR(gcm2(AssemblyLoad{{part(SpherePart{0.2, 0.01}, {0.05, 0, 0.01})}, ""}),
              kgm2_to_gcm2(0.4 * 0.2 * 0.0001 + 0.2 * 0.0025), 1e-6);
  EXPECT_NEAR(gcm2(AssemblyLoad{{part(PointPart{0.1}, {0, 0.04, 0})}, ""}), kgm2_to_gcm2(0.1 * 0.0016), 1e-4);
}

TEST(LoadAssembly, StlCubeAsciiAndBinaryAt50mm) {
  // m a^2 / 6 + m d^2 for a 20 mm cube of 0.1 kg at 50 mm.
  const double expected = kgm2_to_gcm2(0.1 * 0.0004 / 6 + 0.1 * 0.0025);
  for (const char* file : {"cube20_ascii.stl", "cube20_binary.stl"}) {
    const AssemblyLoad a{{part(MeshPart{kData + file, 0.1, 0, 0.001}, {0.05, 0, 0.01})}, ""};
    EXPECT_NEAR(gcm2(a), expected, expected * 0.01) << file;
    const LoadFigures f = load_figures(a);
    EXPECT_NEAR(f.com_m[0], 0.05, 1e-9) << file;
  }
  // Density: 2700 kg/m^3 x 8e-6 m^3 = 21.6 g.
  const LoadFigures f = load_figures(AssemblyLoad{{part(MeshPart{kData + "cube20_binary.stl", 0, 2700, 0.001})}, ""});
  EXPECT_NEAR(f.mass_kg, 0.0216, 1e-6);
}

TEST(LoadAssembly, MeshKeepsTheFilesOwnOrigin_A_TWIN_39) {
  // A CAD export whose cube sits at x = 50 mm, z = 10 mm in the file's own
  // coordinates: at_m [0, 0, 0] keeps it there (MuJoCo re-centres meshes
  // internally; the twin's figures must not).
  const AssemblyLoad a{{part(MeshPart{kData + "cube20_at_50mm.stl", 0.1, 0, 0.001})}, ""};
  const LoadFigures f = load_figures(a);
  EXPECT_NEAR(f.com_m[0], 0.05, 1e-6);
  EXPECT_NEAR(f.com_m[2], 0.01, 1e-6);
  EXPECT_NEAR(kgm2_to_gcm2(f.inertia_kgm2), kgm2_to_gcm2(0.1 * 0.0004 / 6 + 0.1 * 0.0025), 1.0);
}

TEST(LoadAssembly, OpenMeshIsRefusedNamingTheFile) {
  const std::string msg = refusal(AssemblyLoad{{LoadPart{MeshPart{kData + "open_cube20.stl", 0.1, 0, 0.001}, {}, {}, "f.yaml:3:7", ""}}, ""});
  EXPECT_NE(msg.find("f.yaml:3:7"), std::string::npos) << msg;
  EXPECT_NE(msg.find("open_cube20.stl: the mesh is not closed"), std::string::npos) << msg;
}

TEST(LoadAssembly, UserMjcfNamedPlateAndFlangeLoadsAloneAndTwice) {
  const std::string file = kData + "plate_flange_load.xml";
  const double one = 0.1 * (0.06 * 0.06 + 0.06 * 0.06) / 12 + 0.05 * 0.01 * 0.01 / 2;
  EXPECT_NEAR(gcm2(MjcfLoad{file}), kgm2_to_gcm2(one), 1e-6);
  EXPECT_NEAR(gcm2(AssemblyLoad{{part(MjcfLoad{file}), part(MjcfLoad{file}, {0, 0, 0.02})}, ""}), kgm2_to_gcm2(2 * one), 1e-6);
}

TEST(LoadAssembly, LimitHasARelativeTolerance_6_2_64_4) {
  EXPECT_EQ(refusal(ArmLoad{0.15, 0.1, 0}), "(accepted)"); // 15000 computes as 15000.00001
  EXPECT_EQ(refusal(AssemblyLoad{{part(PointPart{0.15}, {0.1, 0, 0.01})}, ""}), "(accepted)");
  const std::string msg = refusal(AssemblyLoad{{part(PointPart{0.2}, {0.1, 0, 0.01}), part(DiskLoad{0.1, 0.05, 0.01})}, "l.yaml:2:3"});
  EXPECT_NE(msg.find("l.yaml:2:3: load inertia about the axis is 21250.0 g cm^2"), std::string::npos) << msg; // rounded
}

TEST(MjcfNamespace, PrefixesOwnNamesAndReferencesOnly) {
  const std::string in = R"(<material name="m"/><geom name="plate" material="m"/><geom material="load_alu"/>)";
  EXPECT_EQ(prefix_mjcf_names(in, "p/"), R"(<material name="p/m"/><geom name="p/plate" material="p/m"/><geom material="load_alu"/>)");
}

TEST(MjcfNamespace, ErrorsBecomeOneLineAtTheUsersLine) {
  const std::string line = mjcf_error_line("MuJoCo error: Error: repeated name 'p/plate' in geom\nObject name = p/plate, id = 2, line = 7, column = 5",
                                           "user.xml", "p/");
  EXPECT_EQ(line.find('\n'), std::string::npos);
  EXPECT_EQ(line.rfind("user.xml:7:5: repeated name 'plate'", 0), 0u) << line;
}

} // namespace
} // namespace sreh
