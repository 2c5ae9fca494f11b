#include "twin/models_dir.hpp"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace sreh {
namespace fs = std::filesystem;

std::string models_dir() {
  std::vector<fs::path> candidates;
  if (const char* env = std::getenv("SREH_TWIN_MODELS_DIR"); env != nullptr && *env != '\0') {
    candidates.emplace_back(env);
  }
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) candidates.push_back(exe.parent_path().parent_path() / "share" / "sreh_twin" / "models");
  candidates.emplace_back(SREH_INSTALLED_MODELS_DIR);
  candidates.emplace_back(SREH_SOURCE_MODELS_DIR);
  std::string tried;
  for (const fs::path& dir : candidates) {
    if (fs::is_regular_file(dir / "sreh50.xml", ec)) return dir.lexically_normal().string();
    tried += (tried.empty() ? "" : ", ") + dir.string();
  }
  throw std::runtime_error("the module model sreh50.xml was not found (looked in " + tried +
                           "; set SREH_TWIN_MODELS_DIR to the models folder)");
}

} // namespace sreh
