#include "twin/mujoco_support.hpp"

#include <cstring>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>

namespace sreh {
namespace {

void throw_error(const char* msg) { throw std::runtime_error(std::string("MuJoCo error: ") + msg); }
void throw_warning(const char* msg) { throw std::runtime_error(std::string("MuJoCo warning: ") + msg); }

struct VfsDeleter {
  void operator()(mjVFS* vfs) const {
    mj_deleteVFS(vfs); // frees every file; mj_deleteFileVFS loops forever in 2.2.2
    delete vfs;
  }
};

} // namespace

void install_mujoco_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    mju_user_error = throw_error;
    mju_user_warning = throw_warning;
  });
}

MjModelPtr compile_mjcf(std::string_view xml, const std::string& origin) { return compile_mjcf(xml, origin, {}); }

MjModelPtr compile_mjcf(std::string_view xml, const std::string& origin, const std::vector<VfsFile>& files) {
  install_mujoco_handlers();
  // mjVFS is ~2 MB: heap, never the stack (mujoco.md).
  std::unique_ptr<mjVFS, VfsDeleter> vfs(new mjVFS);
  mj_defaultVFS(vfs.get());
  static constexpr const char* kName = "sreh_model.xml";
  auto place = [&](const std::string& name, std::string_view bytes) {
    if (mj_makeEmptyFileVFS(vfs.get(), name.c_str(), static_cast<int>(bytes.size())) != 0) {
      throw std::invalid_argument(origin + ": cannot place " + name + " in MuJoCo's virtual file system");
    }
    std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), name.c_str())], bytes.data(), bytes.size());
  };
  place(kName, xml);
  for (const VfsFile& f : files) place(f.name, f.bytes);
  char error[1024] = "";
  mjModel* model = nullptr;
  try {
    model = mj_loadXML(kName, vfs.get(), error, sizeof error);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(origin + ": " + e.what());
  }
  if (model == nullptr) {
    throw std::invalid_argument(origin + ": invalid MJCF: " + error);
  }
  return MjModelPtr(model);
}

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw std::invalid_argument(path + ": cannot open file");
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    throw std::invalid_argument(path + ": read error");
  }
  return text.str();
}

} // namespace sreh
