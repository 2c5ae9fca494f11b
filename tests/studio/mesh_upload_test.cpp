// STL upload in the studio (issue 37): a mesh part's file is checked as the
// load parser reads it, stored with the project, and the project file names
// it so `size --load` / `studio PROJECT.yaml` read it again.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "scenarios/load_file.hpp"
#include "studio/answer.hpp"
#include "studio/mesh_upload.hpp"
#include "studio/project.hpp"
#include "device_logic/units.hpp"
#include "twin/load_figures.hpp"
#include "twin/mujoco_support.hpp"

namespace sreh::studio {
namespace {
namespace fs = std::filesystem;

const std::string kData = std::string(SREH_SOURCE_DIR) + "/tests/twin/data/";

class StudioMeshUpload : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("studio_mesh_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string folder() const { return (dir_ / "meshes").string(); }
  std::size_t files_in_folder() const {
    if (!fs::exists(folder())) return 0;
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(folder()), fs::directory_iterator()));
  }
  std::string error_of(const std::string& name, const std::string& bytes) const {
    try {
      store_mesh(name, bytes, folder());
    } catch (const ProjectError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

TEST_F(StudioMeshUpload, StoresAsciiAndBinaryAsSentUnderTheProjectFolder) {
  for (const char* name : {"cube20_ascii.stl", "cube20_binary.stl"}) {
    const std::string bytes = read_text_file(kData + name);
    const StoredMesh m = store_mesh(name, bytes, folder());
    EXPECT_EQ(m.path, (fs::absolute(folder()) / name).lexically_normal().string());
    EXPECT_EQ(read_text_file(m.path), bytes);
    EXPECT_EQ(m.triangles, 12u);
    EXPECT_NEAR(m.volume, 20.0 * 20 * 20, 1e-3); // a 20 mm cube, in the file's mm
  }
}

TEST_F(StudioMeshUpload, SameFileReusedAnotherOfThatNameGetsASuffix) {
  const std::string ascii = read_text_file(kData + "cube20_ascii.stl");
  const std::string first = store_mesh("part.STL", ascii, folder()).path;
  EXPECT_EQ(fs::path(first).filename(), "part.stl");
  EXPECT_EQ(store_mesh("part.STL", ascii, folder()).path, first);
  const StoredMesh other = store_mesh("part.STL", read_text_file(kData + "cube20_at_50mm.stl"), folder());
  EXPECT_EQ(fs::path(other.path).filename(), "part-2.stl");
  EXPECT_EQ(read_text_file(first), ascii);
  // A picked name with folders and odd characters stays inside the folder.
  EXPECT_EQ(fs::path(store_mesh("../x y/../../evil name.stl", ascii, folder()).path).parent_path(), fs::absolute(folder()));
}

TEST_F(StudioMeshUpload, RefusesAnOpenMeshNamingTheFileAndStoresNothing) {
  const std::string msg = error_of("open_cube20.stl", read_text_file(kData + "open_cube20.stl"));
  EXPECT_EQ(msg.rfind("open_cube20.stl: the mesh is not closed", 0), 0u) << msg;
  EXPECT_EQ(files_in_folder(), 0u);
}

TEST_F(StudioMeshUpload, RefusesWhatIsNotStlAndWhatIsTooBig) {
  std::string msg = error_of("notes.stl", "solid nothing\nendsolid\n");
  EXPECT_EQ(msg, "notes.stl: STL file has no triangles");
  msg = error_of("short.stl", "abc");
  EXPECT_EQ(msg.rfind("short.stl: not an STL file", 0), 0u) << msg;
  msg = error_of("huge.stl", std::string(kMaxMeshUploadBytes + 1, ' '));
  EXPECT_NE(msg.find("huge.stl: 16.0 MB, more than the 16 MB"), std::string::npos) << msg;
  EXPECT_EQ(files_in_folder(), 0u);
}

TEST_F(StudioMeshUpload, MeshFolderIsNextToTheProject) {
  EXPECT_EQ(mesh_folder((dir_ / "p.yaml").string()), (fs::absolute(dir_) / "meshes").lexically_normal().string());
  EXPECT_EQ(mesh_folder(""), (fs::current_path() / "meshes").lexically_normal().string());
}

// A state with a mesh part: its project file reads back as the same state,
// and its figures are `load show`'s of that file (parse_load_file + load_figures).
TEST_F(StudioMeshUpload, ProjectWithAMeshRoundTripsAndSizesItsLoad) {
  const std::string stl = store_mesh("cube20_ascii.stl", read_text_file(kData + "cube20_ascii.stl"), folder()).path;
  const Json state = normalised_state(Json{
      {"name", "mesh project"},
      {"parts", {{{"name", "plate"}, {"shape", "disk"}, {"mass_kg", 0.2}, {"radius_m", 0.04}, {"thickness_m", 0.01}},
                 {{"name", "block"}, {"shape", "mesh"}, {"file", stl}, {"mass_kg", 0.1}, {"scale", 0.001},
                  {"at_m", {0.05, 0, 0.02}}, {"rpy_deg", {0, 0, 30}}}}}});
  const std::string project = (dir_ / "project.yaml").string();
  std::ofstream(project) << project_yaml(state);
  EXPECT_EQ(state_from_project_file(project)["parts"], state["parts"]);
  const LoadFigures cli = load_figures(parse_load_file(project).load);
  const Json panel = load_panel(state);
  EXPECT_DOUBLE_EQ(panel["inertia_gcm2"].get<double>(), kgm2_to_gcm2(cli.inertia_kgm2));
  // A 0.1 kg 20 mm cube 50 mm off the axis: m a^2 / 6 + m d^2 on top of the plate's m r^2 / 2.
  EXPECT_NEAR(panel["parts"][1]["inertia_gcm2"].get<double>(), (0.1 * 0.02 * 0.02 / 6 + 0.1 * 0.05 * 0.05) * 1e7, 0.5);
}

TEST_F(StudioMeshUpload, RelativeMeshPathOpensAsAFullPath) {
  store_mesh("pin.stl", read_text_file(kData + "cube20_binary.stl"), folder());
  const std::string load = (dir_ / "load.yaml").string();
  std::ofstream(load) << "load:\n  parts:\n    - mesh: {file: meshes/pin.stl, mass_kg: 0.03, scale: 0.001}\n      at_m: [0.06, 0, 0.04]\n";
  const Json s = state_from_project_file(load);
  EXPECT_EQ(s["parts"][0]["file"], (fs::absolute(dir_) / "meshes/pin.stl").lexically_normal().string());
  EXPECT_EQ(s["parts"][0]["scale"], 0.001);
  std::ofstream(load) << "load:\n  parts:\n    - mesh: {file: meshes/pin.stl, density_kg_m3: 2700, scale: 0.001}\n";
  try {
    state_from_project_file(load);
    FAIL() << "a mesh given by its density was taken";
  } catch (const ProjectError& e) {
    EXPECT_NE(std::string(e.what()).find("load.yaml:3:13: the studio takes a mesh's mass_kg"), std::string::npos) << e.what();
  }
}

TEST_F(StudioMeshUpload, AMeshPartWithoutItsFileSaysUploadOne) {
  const Json a = answer(Json{{"parts", {{{"shape", "mesh"}, {"mass_kg", 0.1}, {"scale", 0.001}}}}});
  EXPECT_EQ(a.value("error", std::string()), "part 1 (mesh): no STL file yet: upload one");
}

} // namespace
} // namespace sreh::studio
