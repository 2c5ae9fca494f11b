// A load file (`sreh-twin size --load LOAD.yaml`): YAML with a top-level
// `load:` key, exactly as in a scenario (scenarios/README.md); a scenario
// file works too (only its load is used). The scenario parser reads it, so
// keys, limits, errors and MJCF paths behave the same.
#pragma once
#include <string>

#include <yaml-cpp/yaml.h>

#include "scenarios/limits.hpp"
#include "scenarios/scenario.hpp"

namespace sreh {

// Throws ScenarioError "FILE:LINE:COL: ...".
LoadSpec parse_load_text(const std::string& yaml_text, const std::string& file, const std::string& base_dir,
                         const Limits& limits = {});
LoadSpec parse_load_file(const std::string& path, const Limits& limits = {});

// One `load:` value and one `mounting:` value inside a file read elsewhere
// (through detail::load_yaml_safely; sizing cycles): the scenario's keys,
// limits and "FILE:LINE:COL" errors (ScenarioError). `base_dir` resolves an
// MJCF path. Implemented in scenario_parser.cpp.
LoadSpec parse_load_node(const YAML::Node& node, const std::string& file, const std::string& base_dir);
double parse_mounting_node(const YAML::Node& node, const std::string& file); // tilt from vertical, deg

} // namespace sreh
