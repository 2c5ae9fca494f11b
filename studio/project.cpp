#include "studio/project.hpp"

#include <cmath>

#include <fmt/format.h>

#include "scenarios/load_file.hpp"
#include "scenarios/source_loc.hpp"
#include "scenarios/yaml_safety.hpp"

namespace sreh::studio {
namespace {

// The move and options a new project starts with: `size`'s own defaults
// (SizeOptions), a 90 deg move with no target.
Json default_state() {
  const sizing::SizeOptions d;
  return {{"name", "studio project"},
          {"parts", Json::array()},
          {"mounting_tilt_deg", 0.0},
          {"angle_deg", 90.0},
          {"dwell_s", d.dwell_s},
          {"tolerance_deg", d.tolerance_deg},
          {"target", "none"},
          {"target_ms", 300.0},
          {"voltage_V", d.voltage_V},
          {"ambient_C", d.ambient_C},
          {"set", nullptr}};
}

const char* const kOptionKeys[] = {"mounting_tilt_deg", "angle_deg", "dwell_s", "tolerance_deg",
                                   "target_ms", "voltage_V", "ambient_C"};
const char* const kSetKeys[] = {"speed_dps", "accel_pct", "jerk_pct"};

double number(const Json& j, const std::string& what) {
  if (!j.is_number() || !std::isfinite(j.get<double>())) {
    throw ProjectError(fmt::format("{}: expected a number, got {}", what, j.dump()));
  }
  return j.get<double>();
}

const ShapeKeys& shape_keys(const std::string& shape, const std::string& what) {
  for (const ShapeKeys& s : part_shapes()) {
    if (shape == s.shape) return s;
  }
  std::string known;
  for (const ShapeKeys& s : part_shapes()) known += std::string(known.empty() ? "" : ", ") + s.shape;
  throw ProjectError(fmt::format("{}: shape '{}' is not one of {}", what, shape, known));
}

std::array<double, 3> triple(const Json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 3) throw ProjectError(fmt::format("{}: expected [x, y, z], got {}", what, j.dump()));
  return {number(j[0], what + "[0]"), number(j[1], what + "[1]"), number(j[2], what + "[2]")};
}

Json normalised_part(const Json& p, std::size_t k) {
  const std::string what = fmt::format("part {}", k + 1);
  if (!p.is_object()) throw ProjectError(what + ": expected an object");
  const std::string shape = p.value("shape", std::string("disk"));
  const ShapeKeys& keys = shape_keys(shape, what);
  Json out = {{"name", p.value("name", std::string())}, {"shape", shape}};
  if (!out["name"].is_string()) throw ProjectError(what + ": name must be text");
  for (const char* key : keys.keys) {
    if (!p.contains(key)) throw ProjectError(fmt::format("{} ({}): {} missing", what, shape, key));
    out[key] = number(p[key], fmt::format("{} {}", what, key));
  }
  const auto at = p.contains("at_m") ? triple(p["at_m"], what + " at_m") : std::array<double, 3>{};
  const auto rpy = p.contains("rpy_deg") ? triple(p["rpy_deg"], what + " rpy_deg") : std::array<double, 3>{};
  out["at_m"] = at;
  out["rpy_deg"] = rpy;
  return out;
}

std::string num(double v) { return fmt::format("{}", v); }

std::string yaml_text(const std::string& s) { return Json(s).dump(); } // a JSON string is a YAML double-quoted scalar

// A YAML node's number for the state ("FILE:LINE:COL: what").
double yaml_number(const YAML::Node& n, const std::string& file, const std::string& what) {
  try {
    const double v = n.as<double>();
    if (std::isfinite(v)) return v;
  } catch (const YAML::Exception&) {
  }
  const YAML::Mark m = n.Mark();
  throw ProjectError(fmt::format("{}:{}:{}: {}: expected a number", file, m.line + 1, m.column + 1, what));
}

[[noreturn]] void yaml_fail(const YAML::Node& n, const std::string& file, const std::string& message) {
  const YAML::Mark m = n.Mark();
  throw ProjectError(fmt::format("{}:{}:{}: {}", file, m.line + 1, m.column + 1, message));
}

} // namespace

const std::vector<ShapeKeys>& part_shapes() {
  static const std::vector<ShapeKeys> shapes = {
      {"disk", {"mass_kg", "radius_m", "thickness_m"}},
      {"ring", {"mass_kg", "inner_radius_m", "outer_radius_m", "thickness_m"}},
      {"box", {"mass_kg", "x_m", "y_m", "z_m"}},
      {"cylinder", {"mass_kg", "radius_m", "length_m"}},
      {"sphere", {"mass_kg", "radius_m"}},
      {"point", {"mass_kg"}},
  };
  return shapes;
}

Json normalised_state(const Json& state) {
  if (!state.is_object()) throw ProjectError("project: expected a JSON object");
  Json s = default_state();
  if (state.contains("name")) {
    if (!state["name"].is_string()) throw ProjectError("name: expected text");
    s["name"] = state["name"];
  }
  if (state.contains("parts")) {
    if (!state["parts"].is_array()) throw ProjectError("parts: expected a list");
    for (std::size_t k = 0; k < state["parts"].size(); ++k) s["parts"].push_back(normalised_part(state["parts"][k], k));
  }
  for (const char* key : kOptionKeys) {
    if (state.contains(key)) s[key] = number(state[key], key);
  }
  if (state.contains("target")) {
    const Json& t = state["target"];
    if (t != "none" && t != "positioning" && t != "cycle") {
      throw ProjectError(fmt::format("target: expected none, positioning or cycle, got {}", t.dump()));
    }
    s["target"] = t;
  }
  if (state.contains("set") && !state["set"].is_null()) {
    if (!state["set"].is_object()) throw ProjectError("set: expected {speed_dps, accel_pct, jerk_pct} or null");
    const sizing::MotionSetting factory;
    const double defaults[] = {factory.speed_dps, factory.accel_pct, factory.jerk_pct};
    Json set;
    for (std::size_t i = 0; i < 3; ++i) {
      set[kSetKeys[i]] = state["set"].contains(kSetKeys[i]) ? Json(number(state["set"][kSetKeys[i]], std::string("set ") + kSetKeys[i]))
                                                            : Json(defaults[i]);
    }
    s["set"] = set;
  }
  return s;
}

std::string project_yaml(const Json& state_in, double mass_scale) {
  const Json s = normalised_state(state_in);
  std::string o;
  o += "# sreh-twin studio project (docs/studio.md): `sreh-twin studio THIS_FILE` reopens it;\n";
  o += "# the same answer on the command line: " + size_command_line(s, "THIS_FILE") + "\n";
  o += "name: " + yaml_text(s["name"].get<std::string>()) + "\n";
  if (s["parts"].empty()) {
    o += "load: {inertia_gcm2: 0}\n";
  } else {
    o += "load:\n  parts:\n";
    for (const Json& p : s["parts"]) {
      const ShapeKeys& keys = shape_keys(p["shape"].get<std::string>(), "part");
      o += "    - name: " + yaml_text(p["name"].get<std::string>()) + "\n";
      o += fmt::format("      {}: {{", keys.shape);
      for (std::size_t i = 0; i < keys.keys.size(); ++i) {
        double v = p[keys.keys[i]].get<double>();
        if (i == 0) v *= mass_scale; // mass_kg
        o += fmt::format("{}{}: {}", i ? ", " : "", keys.keys[i], num(v));
      }
      o += "}\n";
      o += fmt::format("      at_m: [{}, {}, {}]\n", num(p["at_m"][0]), num(p["at_m"][1]), num(p["at_m"][2]));
      o += fmt::format("      rpy_deg: [{}, {}, {}]\n", num(p["rpy_deg"][0]), num(p["rpy_deg"][1]), num(p["rpy_deg"][2]));
    }
  }
  o += fmt::format("mounting: {{tilt_deg: {}}}\n", num(s["mounting_tilt_deg"].get<double>()));
  o += "studio:\n";
  for (const char* key : {"angle_deg", "dwell_s", "tolerance_deg"}) o += fmt::format("  {}: {}\n", key, num(s[key].get<double>()));
  o += fmt::format("  target: {}\n", s["target"].get<std::string>());
  for (const char* key : {"target_ms", "voltage_V", "ambient_C"}) o += fmt::format("  {}: {}\n", key, num(s[key].get<double>()));
  if (!s["set"].is_null()) {
    o += fmt::format("  set: {{speed_dps: {}, accel_pct: {}, jerk_pct: {}}}\n", num(s["set"]["speed_dps"].get<double>()),
                     num(s["set"]["accel_pct"].get<double>()), num(s["set"]["jerk_pct"].get<double>()));
  }
  return o;
}

Json state_from_project_text(const std::string& text, const std::string& file) {
  // The load and mounting as `size --load` reads them: same keys, limits, errors.
  std::optional<double> tilt;
  try {
    tilt = parse_load_text(text, file, ".").mounting_tilt_deg;
  } catch (const ScenarioError& e) {
    throw ProjectError(e.what());
  }
  const YAML::Node root = detail::load_yaml_safely(text, file, Limits{});
  Json state = {{"parts", Json::array()}};
  if (root["name"]) state["name"] = root["name"].as<std::string>();
  const YAML::Node load = root["load"];
  if (load.IsMap() && load["parts"]) {
    for (const YAML::Node& part : load["parts"]) {
      Json p = {{"name", part["name"] ? part["name"].as<std::string>() : std::string()}};
      const ShapeKeys* found = nullptr;
      for (const ShapeKeys& s : part_shapes()) {
        if (part[s.shape]) found = &s;
      }
      if (!found) yaml_fail(part, file, "the studio builds loads of disk, ring, box, cylinder, sphere and point parts only");
      p["shape"] = found->shape;
      const YAML::Node dims = part[found->shape];
      for (const char* key : found->keys) {
        // The parser checked the part: only a thickness may be left out, its default 0.01 m (twin/specs.hpp).
        p[key] = dims[key] ? Json(yaml_number(dims[key], file, key)) : Json(DiskLoad{}.thickness_m);
      }
      for (const char* key : {"at_m", "rpy_deg"}) {
        Json v = Json::array({0.0, 0.0, 0.0});
        if (part[key]) {
          for (std::size_t i = 0; i < 3; ++i) v[i] = yaml_number(part[key][i], file, key);
        }
        p[key] = v;
      }
      state["parts"].push_back(p);
    }
  } else if (!(load.IsMap() && load["inertia_gcm2"] && load["inertia_gcm2"].as<double>() == 0.0)) {
    yaml_fail(load, file, "the studio builds loads from parts (load: {parts: [...]}); this load is one shape or a file");
  }
  if (tilt) state["mounting_tilt_deg"] = *tilt;
  if (const YAML::Node st = root["studio"]) {
    if (!st.IsMap()) yaml_fail(st, file, "studio: expected a map");
    for (const auto& kv : st) {
      const std::string key = kv.first.as<std::string>();
      if (key == "target") state["target"] = kv.second.as<std::string>();
      else if (key == "set") {
        Json set;
        for (const char* k : kSetKeys) {
          if (kv.second[k]) set[k] = yaml_number(kv.second[k], file, std::string("studio.set.") + k);
        }
        state["set"] = set;
      } else if (key == "angle_deg" || key == "dwell_s" || key == "tolerance_deg" || key == "target_ms" ||
                 key == "voltage_V" || key == "ambient_C") {
        state[key] = yaml_number(kv.second, file, "studio." + key);
      } else {
        yaml_fail(kv.first, file, "studio." + key + ": unknown key (angle_deg, dwell_s, tolerance_deg, target, target_ms, "
                                  "voltage_V, ambient_C, set)");
      }
    }
  }
  try {
    return normalised_state(state);
  } catch (const ProjectError& e) {
    throw ProjectError(fmt::format("{}: {}", file, e.what()));
  }
}

Json state_from_project_file(const std::string& path) {
  std::string text;
  try {
    text = detail::read_limited_file(path, Limits{}, "project file");
  } catch (const ScenarioError& e) {
    throw ProjectError(e.what());
  }
  return state_from_project_text(text, path);
}

sizing::SizeOptions size_options(const Json& state) {
  const Json s = normalised_state(state);
  sizing::SizeOptions o;
  o.angle_deg = s["angle_deg"].get<double>();
  o.voltage_V = s["voltage_V"].get<double>();
  o.dwell_s = s["dwell_s"].get<double>();
  o.tolerance_deg = s["tolerance_deg"].get<double>();
  o.ambient_C = s["ambient_C"].get<double>();
  o.mounting_tilt_deg = s["mounting_tilt_deg"].get<double>();
  if (s["target"] == "positioning") o.max_positioning_ms = s["target_ms"].get<double>();
  if (s["target"] == "cycle") o.max_cycle_ms = s["target_ms"].get<double>();
  if (!s["set"].is_null()) {
    o.speed_dps = s["set"]["speed_dps"].get<double>();
    o.accel_pct = s["set"]["accel_pct"].get<double>();
    o.jerk_pct = s["set"]["jerk_pct"].get<double>();
  }
  return o;
}

std::string size_command_line(const Json& state, const std::string& load_file) {
  const sizing::SizeOptions o = size_options(state);
  std::string c = fmt::format("sreh-twin size --load {} --angle-deg {} --voltage-V {} --dwell-s {} --tolerance-deg {} --ambient-C {}",
                              load_file, num(*o.angle_deg), num(o.voltage_V), num(o.dwell_s), num(o.tolerance_deg),
                              num(o.ambient_C));
  if (o.max_positioning_ms) c += " --max-positioning-ms " + num(*o.max_positioning_ms);
  if (o.max_cycle_ms) c += " --max-cycle-ms " + num(*o.max_cycle_ms);
  if (o.speed_dps) c += fmt::format(" --speed-dps {} --accel-pct {} --jerk-pct {}", num(*o.speed_dps), num(*o.accel_pct), num(*o.jerk_pct));
  return c;
}

} // namespace sreh::studio
