#include "io/output_path.hpp"

#include <sys/stat.h>

#include <filesystem>

namespace sreh::io {
namespace {

namespace fs = std::filesystem;

std::string strip_slashes(std::string p) {
  while (p.size() > 1 && p.back() == '/') p.pop_back();
  return p;
}

fs::path resolved(const std::string& p) {
  std::error_code ec;
  fs::path r = fs::weakly_canonical(fs::absolute(strip_slashes(p)), ec);
  return ec ? fs::absolute(p).lexically_normal() : r;
}

[[noreturn]] void fail(const Output& o, const std::string& what) {
  throw PathError(o.option + " " + o.path + ": " + what);
}

void check_one(const Output& o) {
  if (o.path.empty()) return;
  const bool trailing_slash = o.path.back() == '/';
  const std::string p = strip_slashes(o.path);
  if (o.kind == OutputKind::File && trailing_slash) fail(o, "names a folder; expected a file name");
  const fs::path parent = fs::path(p).parent_path();
  std::error_code ec;
  if (!parent.empty() && !fs::is_directory(parent, ec)) fail(o, "the folder '" + parent.string() + "' does not exist");
  const fs::file_status st = fs::symlink_status(p, ec);
  const fs::file_status target = fs::status(p, ec);
  switch (o.kind) {
    case OutputKind::File:
      if (fs::is_directory(st)) fail(o, "is a folder; expected a file name");
      if (fs::exists(st) && !fs::is_regular_file(st) && !fs::is_symlink(st)) fail(o, "exists and is not a regular file");
      break;
    case OutputKind::Folder:
      if (fs::exists(target) && !fs::is_directory(target)) fail(o, "exists and is not a folder");
      break;
    case OutputKind::EmptyFolder:
      if (fs::exists(st) && !fs::is_directory(st)) fail(o, "exists and is not a folder");
      if (fs::is_directory(st) && !fs::is_empty(p, ec)) fail(o, "exists and is not empty");
      break;
  }
}

} // namespace

bool same_file(const std::string& a, const std::string& b) {
  struct stat sa {}, sb {};
  if (::stat(strip_slashes(a).c_str(), &sa) == 0 && ::stat(strip_slashes(b).c_str(), &sb) == 0) {
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  }
  return resolved(a) == resolved(b);
}

void check_outputs(const std::vector<Output>& outputs, const std::vector<std::string>& inputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const Output& o = outputs[i];
    if (o.path.empty()) continue;
    check_one(o);
    for (const std::string& in : inputs) {
      if (!in.empty() && same_file(o.path, in)) fail(o, "is the input file '" + in + "'; refusing to overwrite it");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (!outputs[j].path.empty() && same_file(o.path, outputs[j].path)) {
        fail(o, "is also the output of " + outputs[j].option);
      }
    }
  }
}

} // namespace sreh::io
