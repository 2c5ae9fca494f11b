// User MJCF in its own namespace (issue 28): a load file may name its
// geoms `plate` or `flange` although the module has names of its own.
// Every name the file defines is prefixed, and so is every reference to
// one of them; references to names the file does not define (the module's
// load_* materials) are left alone. MuJoCo's multi-line errors become one
// line against the user's file and line, with the prefix taken out again.
#pragma once
#include <string>

namespace sreh {

// `text` with every name="X" written name="<prefix>X", and material, mesh,
// texture and hfield references to such names likewise.
std::string prefix_mjcf_names(const std::string& text, const std::string& prefix);

// MuJoCo's error message as one line "<path>:<line>:<column>: <what>" (the
// line and column MuJoCo gives; laid out so that they are the file's own),
// or "<path>: <what>" when MuJoCo gives none. `prefix` is removed.
std::string mjcf_error_line(const std::string& mujoco_message, const std::string& path, const std::string& prefix);

} // namespace sreh
