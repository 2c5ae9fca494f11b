#include "scenarios/atomic_file.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace sreh {

namespace fs = std::filesystem;

void write_file_atomic(const std::string& path, const std::function<void(std::ostream&)>& write) {
  const std::string tmp = path + ".tmp";
  std::error_code ec;
  try {
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      if (!out) throw std::runtime_error("cannot write '" + path + "'");
      write(out);
      out.flush();
      if (!out) throw std::runtime_error("writing '" + path + "' failed");
    }
    fs::rename(tmp, path, ec);
    if (ec) throw std::runtime_error("cannot write '" + path + "': " + ec.message());
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
}

bool output_folder_exists(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  std::error_code ec;
  return parent.empty() || fs::is_directory(parent, ec);
}

} // namespace sreh
