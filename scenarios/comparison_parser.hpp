// Reads a numeric check from YAML (scenarios/README.md "Values"): a number,
// [min, max], "$NAME [+|- N]", or a mapping of eq / ne / lt / gt to a number
// or "$NAME [+|- N]". Names must have been saved earlier in the file.
#pragma once
#include <set>
#include <string>
#include <string_view>

#include <yaml-cpp/yaml.h>

#include "scenarios/comparison.hpp"
#include "scenarios/yaml_reader.hpp"

namespace sreh::detail {

struct NumberSpec {
  double min = 0, max = 0; // allowed plain numbers
  bool integers = false;
  double tol = 0;          // a plain number x means [x - tol, x + tol]; also eq / ne tolerance
};

Comparison read_comparison(const YamlReader& r, const YAML::Node& n, std::string_view what, const NumberSpec& spec,
                           const std::set<std::string>& saved);

// A name for save_as / save: a letter or '_', then letters, digits, '_'.
std::string read_variable_name(const YamlReader& r, const YAML::Node& n, std::string_view what);

} // namespace sreh::detail
