// MuJoCo at the edge (docs/style.md 10, 11): RAII owners, error handlers that
// throw instead of waiting on stdin, and compiling MJCF text from memory.
#pragma once
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <mujoco/mujoco.h>

namespace sreh {

struct MjModelDeleter { void operator()(mjModel* m) const { mj_deleteModel(m); } };
struct MjDataDeleter { void operator()(mjData* d) const { mj_deleteData(d); } };
using MjModelPtr = std::unique_ptr<mjModel, MjModelDeleter>;
using MjDataPtr = std::unique_ptr<mjData, MjDataDeleter>;

// Installs mju_user_error / mju_user_warning handlers that throw
// std::runtime_error("MuJoCo error: ..."): by default MuJoCo waits on stdin
// and exits, and appends warnings to MUJOCO_LOG.TXT (mujoco.md). Idempotent.
void install_mujoco_handlers();

// Compiles MJCF text through a heap-allocated virtual file system (no
// temporary files). Throws std::invalid_argument("<origin>: <MuJoCo message>").
MjModelPtr compile_mjcf(std::string_view xml, const std::string& origin);

// A file placed next to the model in the virtual file system (a load's
// mesh, issue 28): MJCF refers to it by `name` alone.
struct VfsFile {
  std::string name;
  std::string bytes;
  bool operator==(const VfsFile&) const = default;
};
MjModelPtr compile_mjcf(std::string_view xml, const std::string& origin, const std::vector<VfsFile>& files);

// Reads a whole file; throws std::invalid_argument naming the file.
std::string read_text_file(const std::string& path);

} // namespace sreh
