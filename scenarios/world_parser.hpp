// The world block of an input file (issue 30), read by one reader for
// scenario and cycle files alike: the same keys, aliases and ranges, the
// same "FILE:LINE:COL: what" errors (scenarios/README.md "The world",
// A-SCN-32). Internal to the readers of scenarios/ and sizing/.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "scenarios/world.hpp"
#include "scenarios/yaml_reader.hpp"

namespace sreh::detail {

// The top-level keys the world takes (`device:` shares its mapping with a
// scenario's own `nvm_image` and `isdu`; `supply:` and `ambient_C` are the
// aliases of its world keys, A-SCN-32).
inline const std::vector<std::string_view> kWorldTopKeys = {"model", "device", "load", "mounting", "world", "supply",
                                                            "ambient_C"};
// The world's keys inside `device:`.
inline const std::vector<std::string_view> kWorldDeviceKeys = {"supply_V", "ambient_C", "source_resistance_ohm",
                                                               "bus_capacitance_F"};

class WorldReader {
 public:
  // `base_dir` resolves relative file names ("" the current directory).
  WorldReader(const YamlReader& r, std::string base_dir) : r_(r), base_dir_(std::move(base_dir)) {}

  // Every world key of the top-level mapping `root`; `other_device_keys`:
  // what else the caller's `device:` may hold (checked here, read there).
  WorldSetup read(const YAML::Node& root, const WorldRanges& ranges,
                  const std::vector<std::string_view>& other_device_keys) const;

  LoadSpec load(const YAML::Node& n) const;   // a `load:` value (load_parser.hpp)
  double mounting(const YAML::Node& n) const; // a `mounting:` value: tilt from vertical, deg (A-TWIN-24)
  std::vector<HardStop> hard_stops(const YAML::Node& world) const; // a `world:` value

  // A file that must exist, relative to the file's folder or (models/...)
  // to the project's models folder.
  std::string existing_file(const YAML::Node& n, const std::string& what, bool allow_models_dir) const;

 private:
  void supply_and_ambient(const YAML::Node& root, const WorldRanges& ranges, WorldSetup& w) const;
  const YamlReader& r_;
  std::string base_dir_;
};

} // namespace sreh::detail
