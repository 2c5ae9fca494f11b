// The YAML safety layer (issue 12): before yaml-cpp builds a node tree, one
// pass over the parser's events checks what a malicious or broken file could
// do to the tool, and refuses with "FILE:LINE:COL: ..." (exit 2):
//  - file size, valid UTF-8;
//  - nodes after alias expansion (a 2 KB "billion laughs" file would expand
//    to gigabytes when the parser walks it), nesting depth;
//  - more than one document (the rest would be silently ignored);
//  - tags other than the core tags used for a matching value (!!str 5 is a
//    text, never the number 5; !!int abc is refused).
#pragma once
#include <string>

#include <yaml-cpp/yaml.h>

#include "scenarios/limits.hpp"

namespace sreh::detail {

// Reads a whole file of at most limits.max_file_bytes (also from a pipe or
// device: never more than that). Throws ScenarioError naming `path`.
std::string read_limited_file(const std::string& path, const Limits& limits, const std::string& what);

// Checks `text` as above, then loads it. Throws ScenarioError.
YAML::Node load_yaml_safely(const std::string& text, const std::string& file, const Limits& limits);

} // namespace sreh::detail
