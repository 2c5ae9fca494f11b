// A user's MJCF load file made ready to splice into the module (A-TWIN-7,
// issue 28): read, includes expanded, masses checked, every name put into
// the part's own namespace, mesh files read relative to the file and handed
// to MuJoCo from memory, and validated alone so that MuJoCo's errors name
// the user's file and line.
#pragma once
#include <string>
#include <vector>

#include "twin/mujoco_support.hpp"

namespace sreh {

struct LoadXml {
  std::string assets;          // extra <asset> content
  std::string body;            // content for the flange body (or a part's body)
  std::vector<VfsFile> files;  // meshes, by the names the MJCF uses
};

// Relative load paths: as given (working directory), then the source tree.
std::string resolve_load_path(const std::string& path);

// `module_assets`: the module's <asset> content (load_* materials a
// fragment may use). `prefix`: the namespace of this file's names.
// Throws std::invalid_argument "<file>:<line>:<column>: ..." or "<file>: ...".
LoadXml mjcf_load_xml(const std::string& path, const std::string& module_assets, const std::string& prefix);

// A mesh file (STL, ASCII or binary) checked closed and as binary STL under
// `vfs_name`. Throws std::invalid_argument naming the file.
VfsFile mesh_vfs_file(const std::string& path, const std::string& vfs_name);

// The text between <tag ...> and </tag> (first occurrence; empty for <tag/>).
bool inner_of(const std::string& text, const std::string& tag, std::string& inner);

// The same text with every newline and carriage return a blank.
std::string one_line(std::string s);

} // namespace sreh
