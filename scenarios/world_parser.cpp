#include "scenarios/world_parser.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "scenarios/load_file.hpp"
#include "scenarios/load_parser.hpp"
#include "twin/model_card.hpp"
#include "twin/models_dir.hpp"

namespace sreh::detail {
namespace {

namespace fs = std::filesystem;

// A-SCN-1: where a hard stop may stand.
constexpr double kMaxHardStopDeg = 720.0;

// A child of a mapping, or an undefined node (also for a missing parent).
YAML::Node child(const YAML::Node& map, std::string_view key) {
  if (!map || !map.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
  return map[std::string(key)];
}

} // namespace

WorldSetup WorldReader::read(const YAML::Node& root, const WorldRanges& ranges,
                             const std::vector<std::string_view>& other_device_keys) const {
  WorldSetup w;
  if (const YAML::Node m = root["model"]) {
    w.model_loc = r_.loc(m);
    w.model_file = existing_file(m, "model", true);
    try {
      w.module = apply_model_file(default_model_card(), w.model_file).module_model();
    } catch (const ModelCardError& e) {
      r_.fail(m, std::string("model: ") + e.what());
    }
  }
  if (const YAML::Node d = root["device"]) {
    std::vector<std::string_view> allowed = kWorldDeviceKeys;
    allowed.insert(allowed.end(), other_device_keys.begin(), other_device_keys.end());
    r_.check_map(d, "device", allowed);
  }
  if (const YAML::Node s = root["supply"]) {
    r_.check_map(s, "supply", {"voltage_V", "source_resistance_ohm", "bus_capacitance_F"});
  }
  supply_and_ambient(root, ranges, w);
  if (const YAML::Node l = root["load"]) {
    w.load_loc = r_.loc(l);
    w.load = load(l);
  }
  if (root["mounting"]) w.mounting_tilt_deg = mounting(root["mounting"]);
  if (root["world"]) w.hard_stops = hard_stops(root["world"]);
  return w;
}

// A-SCN-32: `device.supply_V` (canonical) or `supply.voltage_V` (alias),
// and so on; the key as written names the value in messages.
void WorldReader::supply_and_ambient(const YAML::Node& root, const WorldRanges& ranges, WorldSetup& w) const {
  struct Field {
    std::string_view key, alias_parent, alias_key;
    double min, max;
    double& out;
  };
  const Field fields[] = {
      {"supply_V", "supply", "voltage_V", ranges.min_supply_V, ranges.max_supply_V, w.supply.voltage_V},
      {"ambient_C", "", "ambient_C", ranges.min_ambient_C, ranges.max_ambient_C, w.thermal.ambient_C},
      {"source_resistance_ohm", "supply", "source_resistance_ohm", 0.0, kMaxSourceResistance_ohm,
       w.supply.source_resistance_ohm},
      {"bus_capacitance_F", "supply", "bus_capacitance_F", 0.0, kMaxBusCapacitance_F, w.supply.bus_capacitance_F},
  };
  for (const Field& f : fields) {
    const YAML::Node main = child(root["device"], f.key);
    const YAML::Node alias = f.alias_parent.empty() ? child(root, f.alias_key) : child(root[std::string(f.alias_parent)], f.alias_key);
    const std::string main_what = join_path("device", f.key);
    const std::string alias_what = f.alias_parent.empty() ? std::string(f.alias_key) : join_path(f.alias_parent, f.alias_key);
    if (main && alias) r_.fail(alias, fmt::format("{}: the same as {}; give one of them", alias_what, main_what));
    if (main) f.out = r_.number(main, main_what, f.min, f.max);
    if (alias) f.out = r_.number(alias, alias_what, f.min, f.max);
  }
}

LoadSpec WorldReader::load(const YAML::Node& n) const {
  return parse_load_value(r_, n, [this](const YAML::Node& f, const std::string& what) {
    return existing_file(f, what, true);
  });
}

// Axis orientation (A-TWIN-24): {axis: vertical|horizontal} or {tilt_deg: T}.
double WorldReader::mounting(const YAML::Node& n) const {
  r_.check_map(n, "mounting", {"axis", "tilt_deg"});
  if (n["axis"] && n["tilt_deg"]) r_.fail(n, "mounting: give either axis or tilt_deg, not both");
  if (n["tilt_deg"]) {
    return r_.number(n["tilt_deg"], "mounting.tilt_deg", kMinMountingTiltDeg, kMaxMountingTiltDeg);
  }
  if (n["axis"]) {
    const std::string axis = r_.text(n["axis"], "mounting.axis");
    if (axis == "vertical") return 0.0;
    if (axis == "horizontal") return 90.0;
    r_.fail(n["axis"], "mounting.axis: expected vertical or horizontal, got '" + axis + "'");
  }
  r_.fail(n, "mounting: expected {axis: vertical|horizontal} or {tilt_deg: T}");
}

std::vector<HardStop> WorldReader::hard_stops(const YAML::Node& n) const {
  r_.check_map(n, "world", {"hard_stops"});
  std::vector<HardStop> stops;
  if (const YAML::Node list = n["hard_stops"]) {
    if (!list.IsSequence()) r_.fail(list, "world.hard_stops: expected a list of {angle_deg: A}");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string what = fmt::format("world.hard_stops[{}]", i);
      r_.check_map(list[i], what, {"angle_deg"});
      stops.push_back(HardStop{r_.number(r_.require(list[i], "angle_deg", what), what + ".angle_deg",
                                         -kMaxHardStopDeg, kMaxHardStopDeg)});
    }
  }
  return stops;
}

std::string WorldReader::existing_file(const YAML::Node& n, const std::string& what, bool allow_models_dir) const {
  const std::string p = r_.text(n, what);
  if (p.empty()) r_.fail(n, what + ": empty path");
  std::vector<fs::path> tried;
  const fs::path given(p);
  tried.push_back(given.is_absolute() || base_dir_.empty() ? given : fs::path(base_dir_) / given);
  if (allow_models_dir && !given.is_absolute() && p.rfind("models/", 0) == 0) {
    tried.push_back(fs::path(models_dir()).parent_path() / given); // twin/models_dir.hpp
  }
  for (const auto& t : tried) {
    std::error_code ec;
    if (fs::is_regular_file(t, ec)) return t.lexically_normal().string();
  }
  r_.fail(n, fmt::format("{}: file '{}' not found (looked for {})", what, p, tried.front().lexically_normal().string()));
}

} // namespace sreh::detail

namespace sreh {

LoadSpec parse_load_node(const YAML::Node& node, const std::string& file, const std::string& base_dir) {
  const detail::YamlReader r(file);
  return detail::WorldReader(r, base_dir).load(node);
}

double parse_mounting_node(const YAML::Node& node, const std::string& file) {
  const detail::YamlReader r(file);
  return detail::WorldReader(r, "").mounting(node);
}

} // namespace sreh
