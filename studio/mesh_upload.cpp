#include "studio/mesh_upload.hpp"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <stdexcept>

#include <fmt/format.h>

#include "studio/project.hpp"
#include "twin/mujoco_support.hpp"
#include "twin/stl_mesh.hpp"

namespace sreh::studio {
namespace fs = std::filesystem;
namespace {

// The stem a stored file gets: the picked name without folder and `.stl`,
// letters, digits, '-', '_' and '.' kept, anything else '_'.
std::string safe_stem(const std::string& name) {
  std::string stem = fs::path(name).filename().string();
  if (stem.size() > 4 && fs::path(stem).extension().string().size() == 4) {
    std::string ext = fs::path(stem).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".stl") stem.resize(stem.size() - 4);
  }
  std::string out;
  for (char c : stem) out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' ? c : '_';
  if (out.empty() || out.front() == '.') out = "mesh" + out;
  return out.substr(0, 80);
}

bool same_file(const fs::path& p, const std::string& bytes) {
  std::error_code ec;
  if (fs::file_size(p, ec) != bytes.size() || ec) return false;
  return read_text_file(p.string()) == bytes;
}

} // namespace

std::string mesh_folder(const std::string& project_file) {
  const fs::path base = project_file.empty() ? fs::current_path() : fs::absolute(project_file).parent_path();
  return (base / "meshes").lexically_normal().string();
}

StoredMesh store_mesh(const std::string& name_in, const std::string& bytes, const std::string& folder) {
  const std::string name = name_in.empty() ? std::string("the uploaded file") : fs::path(name_in).filename().string();
  if (bytes.size() > kMaxMeshUploadBytes) {
    throw ProjectError(fmt::format("{}: {:.1f} MB, more than the {} MB an STL upload may have", name,
                                   static_cast<double>(bytes.size()) / (1 << 20), kMaxMeshUploadBytes >> 20));
  }
  StlMesh mesh;
  try {
    mesh = parse_stl(bytes, name);
    check_closed_mesh(mesh, name);
  } catch (const std::invalid_argument& e) {
    throw ProjectError(e.what());
  }
  static std::mutex storing; // two uploads of one name at once: the second sees the first's file
  const std::lock_guard<std::mutex> lock(storing);
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw ProjectError(fmt::format("{}: cannot make the folder {} for it: {}", name, folder, ec.message()));
  const std::string stem = safe_stem(name);
  fs::path target;
  for (int k = 1; k <= 1000; ++k) {
    const fs::path p = fs::absolute(fs::path(folder) / (k == 1 ? stem + ".stl" : fmt::format("{}-{}.stl", stem, k)));
    if (!fs::exists(p) || same_file(p, bytes)) {
      target = p;
      break;
    }
  }
  if (target.empty()) throw ProjectError(fmt::format("{}: {} holds 1000 other files of that name", name, folder));
  if (!fs::exists(target)) { // written to a temporary name and renamed: never half a file under its name
    const fs::path part = target.string() + ".part";
    {
      std::ofstream out(part, std::ios::binary);
      out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      if (!out.flush()) {
        fs::remove(part, ec);
        throw ProjectError(fmt::format("{}: cannot write {}", name, part.string()));
      }
    }
    fs::rename(part, target, ec);
    if (ec) {
      fs::remove(part, ec);
      throw ProjectError(fmt::format("{}: cannot store it as {}", name, target.string()));
    }
  }
  return {target.lexically_normal().string(), mesh.triangles.size(), stl_volume(mesh)};
}

} // namespace sreh::studio
