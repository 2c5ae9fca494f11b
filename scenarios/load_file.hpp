// A load file (`sreh-twin size --load LOAD.yaml`): YAML with a top-level
// `load:` key, exactly as in a scenario (scenarios/README.md), an optional
// `mounting:` and `name:`/`description:`; a scenario file works too (it is
// checked as a whole scenario, only its load and mounting are used). One
// loader for every caller (issue 13): the scenario parser's own load and
// mounting readers, keys, limits and "FILE:LINE:COL" errors.
#pragma once
#include <optional>
#include <string>

#include <yaml-cpp/yaml.h>

#include "scenarios/limits.hpp"
#include "scenarios/scenario.hpp"

namespace sreh {

struct LoadFileContents {
  LoadSpec load;
  std::optional<double> mounting_tilt_deg; // given only when the file has `mounting:`
  std::string name;                        // the file's `name:` (a scenario's name), or empty
};

// Throws ScenarioError "FILE:LINE:COL: ...".
LoadFileContents parse_load_text(const std::string& yaml_text, const std::string& file, const std::string& base_dir,
                                 const Limits& limits = {});
LoadFileContents parse_load_file(const std::string& path, const Limits& limits = {});

// One `load:` value and one `mounting:` value inside a file read elsewhere
// (through detail::load_yaml_safely; sizing cycles): the scenario's keys,
// limits and "FILE:LINE:COL" errors (ScenarioError). `base_dir` resolves an
// MJCF path. Implemented in world_parser.cpp.
LoadSpec parse_load_node(const YAML::Node& node, const std::string& file, const std::string& base_dir);
double parse_mounting_node(const YAML::Node& node, const std::string& file); // tilt from vertical, deg

// The mounting tilt's range wherever a user gives it (a scenario's and a load
// file's mounting:, size, calibrate --plan; issue 39: one range): the axis
// vertical to upside down (A-TWIN-24).
inline constexpr double kMinMountingTiltDeg = 0.0;
inline constexpr double kMaxMountingTiltDeg = 180.0;

} // namespace sreh
