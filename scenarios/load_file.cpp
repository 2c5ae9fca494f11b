#include "scenarios/load_file.hpp"

#include <filesystem>

#include "scenarios/scenario_parser.hpp"
#include "scenarios/yaml_reader.hpp"
#include "scenarios/yaml_safety.hpp"

namespace sreh {

LoadFileContents parse_load_text(const std::string& yaml_text, const std::string& file, const std::string& base_dir,
                                 const Limits& limits) {
  const YAML::Node root = detail::load_yaml_safely(yaml_text, file, limits);
  if (!root.IsMap() || !root["load"]) {
    throw ScenarioError(SourceLoc{file, 1, 1},
                        "expected a top-level 'load:' key (e.g. load: {disk: {mass_kg: 0.4, radius_m: 0.1}})");
  }
  if (root["steps"]) { // a whole scenario: its parser checks all of it
    const Scenario sc = parse_scenario_text(yaml_text, file, base_dir, limits);
    return {sc.world.load, root["mounting"] ? std::optional<double>(sc.world.mounting_tilt_deg) : std::nullopt, sc.name};
  }
  const detail::YamlReader reader(file);
  // `studio:`: a studio project's move and options (docs/studio.md), for `sreh-twin studio` only.
  reader.check_map(root, "load file", {"name", "description", "load", "mounting", "studio"});
  for (const char* key : {"name", "description"}) {
    if (root[key]) (void)reader.text(root[key], key);
  }
  LoadFileContents contents{parse_load_node(root["load"], file, base_dir), std::nullopt, {}};
  if (root["name"]) contents.name = reader.text(root["name"], "name");
  if (root["mounting"]) contents.mounting_tilt_deg = parse_mounting_node(root["mounting"], file);
  return contents;
}

LoadFileContents parse_load_file(const std::string& path, const Limits& limits) {
  const std::string text = detail::read_limited_file(path, limits, "load file");
  return parse_load_text(text, path, std::filesystem::path(path).parent_path().string(), limits);
}

} // namespace sreh
