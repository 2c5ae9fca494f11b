// The `load:` value of scenarios, load files and sizing cycles (issue 28):
// one shape (the forms of issue 5) or an assembly `parts: [...]`, each part
// one shape plus `at_m` and `rpy_deg`. Internal to the scenario parser.
// The load is built once while parsing, so a load the twin refuses (above
// 15000 g cm^2, an open mesh, invalid MJCF) is an error at its own line.
#pragma once
#include <functional>
#include <string>

#include <yaml-cpp/yaml.h>

#include "scenarios/yaml_reader.hpp"
#include "twin/specs.hpp"

namespace sreh::detail {

// Resolves a file named at a node (relative to the naming file's folder);
// fails with the node's location if it does not exist.
using FileResolver = std::function<std::string(const YAML::Node& node, const std::string& what)>;

LoadSpec parse_load_value(const YamlReader& r, const YAML::Node& node, const FileResolver& resolve);

} // namespace sreh::detail
