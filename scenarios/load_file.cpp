#include "scenarios/load_file.hpp"

#include <filesystem>

#include "scenarios/scenario_parser.hpp"
#include "scenarios/yaml_safety.hpp"

namespace sreh {

LoadSpec parse_load_text(const std::string& yaml_text, const std::string& file, const std::string& base_dir,
                         const Limits& limits) {
  const YAML::Node root = detail::load_yaml_safely(yaml_text, file, limits);
  if (!root.IsMap() || !root["load"]) {
    throw ScenarioError(SourceLoc{file, 1, 1},
                        "expected a top-level 'load:' key (e.g. load: {disk: {mass_kg: 0.4, radius_m: 0.1}})");
  }
  // Keys a scenario needs are appended at the end: every line number stays.
  std::string text = yaml_text;
  if (!root["name"]) text += "\nname: load from " + std::filesystem::path(file).filename().string() + "\n";
  if (!root["steps"]) text += "\nsteps:\n  - comment: sizing load\n";
  Limits appended = limits;
  appended.max_file_bytes += 256;
  return parse_scenario_text(text, file, base_dir, appended).load;
}

LoadSpec parse_load_file(const std::string& path, const Limits& limits) {
  const std::string text = detail::read_limited_file(path, limits, "load file");
  return parse_load_text(text, path, std::filesystem::path(path).parent_path().string(), limits);
}

} // namespace sreh
