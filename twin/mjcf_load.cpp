#include "twin/mjcf_load.hpp"

#include <filesystem>
#include <mutex>
#include <regex>
#include <set>
#include <stdexcept>

#include "twin/mjcf_checks.hpp"
#include "twin/mjcf_namespace.hpp"
#include "twin/models_dir.hpp"
#include "twin/stl_mesh.hpp"

namespace sreh {
namespace {

namespace fs = std::filesystem;

// Replaces every character of [begin, end) except newlines with blanks, so
// MuJoCo's line numbers in error messages still match the user's file.
void blank_out(std::string& text, std::size_t begin, std::size_t end) {
  for (std::size_t i = begin; i < end && i < text.size(); ++i) {
    if (text[i] != '\n') text[i] = ' ';
  }
}

// The load validations that passed (issue 37). A twin composes its model,
// and so reads its MJCF load, each time it is built (sizing builds one per
// sampled model card); compiling the load alone makes MuJoCo's default
// mjData (13 MB zeroed): half of `size --uncertainty`'s CPU time with an
// MJCF load. The same text with the same meshes passes again, so it is
// compiled once; a failure is not kept (it is compiled and thrown anew).
class ValidatedLoads {
 public:
  bool contains(const std::string& key) {
    std::lock_guard<std::mutex> lock(mutex_);
    return passed_.count(key) > 0;
  }
  void add(const std::string& key) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (passed_.size() >= 64) passed_.clear(); // bounded in a long-running studio or server
    passed_.insert(key);
  }

 private:
  std::mutex mutex_;
  std::set<std::string> passed_;
};

ValidatedLoads& validated_loads() {
  static ValidatedLoads loads;
  return loads;
}

// <mesh file="F"> inside the user's file: F relative to the file's folder
// (and its compiler meshdir), read by the twin and renamed to a
// virtual-file-system name that cannot clash with another part's.
std::string take_mesh_files(std::string text, const fs::path& dir, const std::string& path, const std::string& prefix,
                            std::vector<VfsFile>& files) {
  static const std::regex meshdir(R"re(\bmeshdir\s*=\s*"([^"]*)")re");
  static const std::regex file_attr(R"re((<mesh\b[^>]*\bfile\s*=\s*")([^"]*)")re");
  fs::path mesh_dir = dir;
  std::smatch m;
  if (std::regex_search(text, m, meshdir)) {
    mesh_dir = dir / m[1].str();
    blank_out(text, static_cast<std::size_t>(m.position(0)), static_cast<std::size_t>(m.position(0) + m.length(0)));
  }
  std::string out;
  std::size_t last = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), file_attr); it != std::sregex_iterator(); ++it) {
    const std::smatch& f = *it;
    const fs::path given(f[2].str());
    const fs::path file = given.is_absolute() ? given : mesh_dir / given;
    const std::string ext = file.extension().string();
    if (ext != ".stl" && ext != ".STL") {
      throw std::invalid_argument(path + ": <mesh file=\"" + f[2].str() + "\">: only STL meshes are supported (A-TWIN-7)");
    }
    const std::string vfs_name = "sreh_" + std::to_string(files.size()) + "_" + prefix + ".stl";
    files.push_back(mesh_vfs_file(file.string(), vfs_name));
    out += text.substr(last, static_cast<std::size_t>(f.position(0)) - last) + f[1].str() + vfs_name + "\"";
    last = static_cast<std::size_t>(f.position(0) + f.length(0));
  }
  return out + text.substr(last);
}

} // namespace

bool inner_of(const std::string& text, const std::string& tag, std::string& inner) {
  const std::size_t open = text.find("<" + tag);
  if (open == std::string::npos) return false;
  const std::size_t open_end = text.find('>', open);
  if (open_end == std::string::npos) return false;
  if (text[open_end - 1] == '/') { inner.clear(); return true; } // <tag/>
  const std::size_t close = text.find("</" + tag + ">", open_end);
  if (close == std::string::npos) return false;
  inner = text.substr(open_end + 1, close - open_end - 1);
  return true;
}

std::string one_line(std::string s) {
  for (char& c : s) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return s;
}

std::string resolve_load_path(const std::string& path) {
  if (path.empty()) throw std::invalid_argument("MJCF load: empty file name");
  if (fs::path(path).is_relative() && !fs::exists(path)) {
    const fs::path in_tree = fs::path(models_dir()).parent_path() / path;
    if (fs::exists(in_tree)) return in_tree.string();
  }
  return path;
}

VfsFile mesh_vfs_file(const std::string& path, const std::string& vfs_name) {
  const StlMesh mesh = read_stl_file(path);
  check_closed_mesh(mesh, path);
  return VfsFile{vfs_name, binary_stl(mesh)};
}

LoadXml mjcf_load_xml(const std::string& given_path, const std::string& module_assets, const std::string& prefix) {
  const std::string path = resolve_load_path(given_path);
  std::string text = read_text_file(path);
  if (const std::size_t decl = text.find("<?xml"); decl != std::string::npos) {
    blank_out(text, decl, text.find("?>", decl) + 2);
  }
  // Comments may mention <mujoco> or <body>: blank them before looking.
  for (std::size_t at = text.find("<!--"); at != std::string::npos; at = text.find("<!--", at)) {
    const std::size_t end = text.find("-->", at);
    if (end == std::string::npos) break; // left for MuJoCo's parser to report
    blank_out(text, at, end + 3);
  }
  // Includes relative to the including file; masses checked (issue 12).
  const fs::path dir = fs::path(path).parent_path();
  text = expand_mjcf_includes(text, dir.string(), path);
  check_mjcf_inertials(text, path);
  LoadXml parts;
  text = take_mesh_files(text, dir, path, prefix, parts.files);
  text = prefix_mjcf_names(text, prefix); // names stay on their lines
  const std::string base_assets = "<asset>" + one_line(module_assets) + "</asset>";
  std::string validation;
  if (const std::size_t root = text.find("<mujoco"); root != std::string::npos) {
    if (text.find("angle=\"radian\"") == std::string::npos) {
      throw std::invalid_argument(path + ": a <mujoco> load file must declare <compiler angle=\"radian\"/> (docs/style.md 6)");
    }
    if (text.find("<default") != std::string::npos) {
      throw std::invalid_argument(path + ": <default> classes are not supported in load files; set attributes on the elements");
    }
    if (!inner_of(text, "worldbody", parts.body)) {
      throw std::invalid_argument(path + ": a <mujoco> load file needs a <worldbody> holding the load's <body>");
    }
    std::string assets;
    if (inner_of(text, "asset", assets)) parts.assets = assets;
    const std::size_t root_end = text.find('>', root);
    validation = text;
    validation.insert(root_end + 1, base_assets);
  } else {
    if (text.find("<body") == std::string::npos) {
      throw std::invalid_argument(path + ": no <body> element: a load file holds one <body> (or a <mujoco> document with one)");
    }
    parts.body = text;
    validation = "<mujoco model=\"load\"><compiler angle=\"radian\" autolimits=\"true\"/>" + base_assets +
                 "<worldbody>" + text + "\n</worldbody></mujoco>";
  }
  std::string key = path + '\n' + prefix + '\n' + validation;
  for (const VfsFile& f : parts.files) key += '\n' + f.name + '\n' + f.bytes;
  if (validated_loads().contains(key)) return parts;
  try {
    const MjModelPtr alone = compile_mjcf(validation, path, parts.files);
    check_compiled_inertials(alone.get(), path); // masses MuJoCo derived from geoms (density x volume)
  } catch (const std::invalid_argument& e) {
    std::string why = e.what();
    if (why.rfind(path + ": ", 0) == 0) why.erase(0, path.size() + 2);
    throw std::invalid_argument(mjcf_error_line(why, path, prefix));
  }
  validated_loads().add(key);
  return parts;
}

} // namespace sreh
