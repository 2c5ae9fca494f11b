// The cycle file (docs/sizing.md "Cycles"): read through the YAML safety
// layer (size, nodes, depth, tags; scenarios/yaml_safety.hpp), every key
// checked with the scenario reader, the world (model, device or supply and
// ambient, load, mounting, hard stops) by the scenario's own world reader
// (scenarios/world_parser.hpp), so a key means the same as in a scenario.
// Every error: "FILE:LINE:COL: what" (exit 2).
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "device_logic/parameter_ids.hpp"
#include "device_logic/units.hpp"
#include "scenarios/world_parser.hpp"
#include "scenarios/yaml_reader.hpp"
#include "scenarios/yaml_safety.hpp"
#include "sizing/cycle.hpp"

namespace sreh::sizing {
namespace {

using detail::YamlReader;

// A-SIZE-1 and A-SIZE-17: plausibility limits of a cycle.
constexpr int kMaxSegments = 200;
constexpr double kMaxProcessTorque_Nm = 5.0; // far above the motor's 0.6 N m: such a cycle is judged, not refused

class CycleParser {
 public:
  CycleParser(const std::string& file, std::string base_dir) : r_(file), world_(r_, std::move(base_dir)) {}

  CycleRequest parse(const YAML::Node& root) {
    if (!root.IsDefined() || root.IsNull()) r_.fail(root, "empty cycle file (expected segments: [...])");
    std::vector<std::string_view> keys = {"name", "description"};
    keys.insert(keys.end(), detail::kWorldTopKeys.begin(), detail::kWorldTopKeys.end());
    keys.insert(keys.end(), {"process_torque_Nm", "tolerance_deg", "wait_ms", "timeout_ms", "thermal_margin_K",
                             "handshake_cycles", "cycles", "segments", "studio"});
    r_.check_map(root, "cycle", keys);
    CycleRequest c;
    c.file = r_.file();
    if (root["name"]) (void)r_.text(root["name"], "name");
    if (root["description"]) (void)r_.text(root["description"], "description");
    // `studio:`: a studio project's options (docs/studio.md), for `sreh-twin studio` only.
    // The world as in a scenario (A-SCN-32), narrowed to what a sizing takes.
    c.world = world_.read(root, sizing_world_ranges(), {});
    if (root["process_torque_Nm"]) c.process_torque_Nm = torque(root["process_torque_Nm"], "process_torque_Nm", 0.0);
    const param::MotionSet set(0); // the rows every set shares (manual 6.2)
    if (root["tolerance_deg"]) c.settling.tolerance_deg = r_.row_number(root["tolerance_deg"], "tolerance_deg", set.tolerance);
    if (root["wait_ms"]) c.settling.wait_ms = r_.row_number(root["wait_ms"], "wait_ms", set.waiting_time);
    if (root["timeout_ms"]) c.settling.timeout_ms = r_.row_number(root["timeout_ms"], "timeout_ms", set.settling_timeout);
    if (root["thermal_margin_K"]) {
      c.thermal_margin_K = r_.number(root["thermal_margin_K"], "thermal_margin_K", 0.0, kMaxThermalMargin_K);
    }
    if (root["handshake_cycles"]) {
      c.handshake_cycles = static_cast<int>(r_.integer(root["handshake_cycles"], "handshake_cycles", 0, 100));
    }
    if (root["cycles"]) c.cycles = static_cast<int>(r_.integer(root["cycles"], "cycles", 2, 20));
    const YAML::Node list = r_.require(root, "segments", "cycle");
    if (!list.IsSequence() || list.size() == 0) r_.fail(list, "segments: expected a list of {move_deg: A}, {dwell_s: T}, {load: ...}");
    if (list.size() > static_cast<std::size_t>(kMaxSegments)) {
      r_.fail(list, fmt::format("segments: {} segments, at most {} (A-SIZE-17)", list.size(), kMaxSegments));
    }
    bool any_move = false;
    for (std::size_t i = 0; i < list.size(); ++i) {
      c.segments.push_back(segment(list[i], fmt::format("segments[{}]", i)));
      any_move = any_move || std::holds_alternative<CycleMove>(c.segments.back().what);
    }
    if (!any_move) r_.fail(list, "segments: a cycle needs at least one move ({move_deg: A})");
    return c;
  }

 private:
  double torque(const YAML::Node& n, const std::string& what, double min) const {
    return r_.number(n, what, min, kMaxProcessTorque_Nm);
  }

  CycleSegment segment(const YAML::Node& n, const std::string& what) {
    if (!n.IsMap()) r_.fail(n, what + ": expected {move_deg: A}, {dwell_s: T} or {load: ...}");
    CycleSegment seg;
    const SourceLoc loc = r_.loc(n);
    seg.line = loc.line;
    seg.column = loc.column;
    const int kinds = (n["move_deg"] ? 1 : 0) + (n["dwell_s"] ? 1 : 0) + (n["load"] ? 1 : 0);
    if (kinds != 1) r_.fail(n, what + ": give exactly one of move_deg, dwell_s, load");
    if (n["move_deg"]) {
      r_.check_map(n, what, {"move_deg", "relative", "parameter_set", "speed_dps", "accel_pct", "jerk_pct",
                             "process_torque_Nm"});
      CycleMove m;
      m.target_deg = r_.number(n["move_deg"], what + ".move_deg", -kMaxAngle_deg, kMaxAngle_deg);
      if (n["relative"]) m.relative = r_.boolean(n["relative"], what + ".relative");
      if (m.relative && !at_least_one_count(m.target_deg)) {
        r_.fail(n["move_deg"], what + ".move_deg: a relative move needs at least one position count (360/65536 deg)");
      }
      if (n["parameter_set"]) m.parameter_set = static_cast<int>(r_.integer(n["parameter_set"], what + ".parameter_set", 0, param::kMotionSets - 1));
      const param::MotionSet set(0);
      if (n["speed_dps"]) m.speed_dps = r_.row_number(n["speed_dps"], what + ".speed_dps", set.speed);
      if (n["accel_pct"]) m.accel_pct = r_.row_number(n["accel_pct"], what + ".accel_pct", set.acceleration);
      if (n["jerk_pct"]) m.jerk_pct = r_.row_number(n["jerk_pct"], what + ".jerk_pct", set.jerk);
      if (n["process_torque_Nm"]) m.process_torque_Nm = torque(n["process_torque_Nm"], what + ".process_torque_Nm", 0.0);
      seg.what = m;
    } else if (n["dwell_s"]) {
      r_.check_map(n, what, {"dwell_s", "process_torque_Nm"});
      CycleDwell d;
      d.dwell_s = r_.number(n["dwell_s"], what + ".dwell_s", 0.0, kMaxDwell_s);
      if (n["process_torque_Nm"]) {
        d.process_torque_Nm = torque(n["process_torque_Nm"], what + ".process_torque_Nm", -kMaxProcessTorque_Nm);
      }
      seg.what = d;
    } else {
      r_.check_map(n, what, {"load"});
      seg.what = CycleLoadChange{world_.load(n["load"])};
    }
    return seg;
  }

  static bool at_least_one_count(double deg) { return deg_to_wire_counts(deg) != 0; } // manual 2.5

  YamlReader r_;
  detail::WorldReader world_;
};

} // namespace

CycleRequest parse_cycle_text(const std::string& text, const std::string& file, const std::string& base_dir) {
  try {
    const YAML::Node root = detail::load_yaml_safely(text, file, Limits{});
    return CycleParser(file, base_dir).parse(root);
  } catch (const ScenarioError& e) {
    throw SizingInputError(e.what());
  } catch (const YAML::Exception& e) { // a conversion the checks did not foresee
    throw SizingInputError(fmt::format("{}:{}:{}: {}", file, e.mark.is_null() ? 0 : e.mark.line + 1,
                                       e.mark.is_null() ? 0 : e.mark.column + 1, e.msg));
  }
}

CycleRequest parse_cycle_file(const std::string& path) {
  std::string text;
  try {
    text = detail::read_limited_file(path, Limits{}, "cycle file");
  } catch (const ScenarioError& e) {
    throw SizingInputError(e.what());
  }
  return parse_cycle_text(text, path, std::filesystem::path(path).parent_path().string());
}

} // namespace sreh::sizing
