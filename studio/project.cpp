#include "studio/project.hpp"

#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "scenarios/load_file.hpp"
#include "scenarios/source_loc.hpp"
#include "scenarios/yaml_safety.hpp"
#include "sizing/cycle.hpp"

namespace sreh::studio {
namespace {

// A new cycle (docs/studio.md "Cycles"): pick and place, as
// examples/cycles/pick_and_place.yaml moves.
Json default_segments() {
  return Json::array({{{"kind", "move"}, {"deg", 90.0}, {"relative", false}},
                      {{"kind", "dwell"}, {"s", 0.2}},
                      {{"kind", "grip"}},
                      {{"kind", "move"}, {"deg", 0.0}, {"relative", false}},
                      {{"kind", "dwell"}, {"s", 0.2}},
                      {{"kind", "release"}}});
}

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
          {"set", nullptr},
          {"mode", "single"},
          {"segments", default_segments()},
          {"uncertainty", false}};
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
  if (shape == "mesh") { // the stored STL (mesh_upload.hpp)
    if (!p.contains("file") || !p["file"].is_string() || p["file"].get<std::string>().empty()) {
      throw ProjectError(what + " (mesh): no STL file yet: upload one");
    }
    out["file"] = p["file"];
  }
  const auto at = p.contains("at_m") ? triple(p["at_m"], what + " at_m") : std::array<double, 3>{};
  const auto rpy = p.contains("rpy_deg") ? triple(p["rpy_deg"], what + " rpy_deg") : std::array<double, 3>{};
  out["at_m"] = at;
  out["rpy_deg"] = rpy;
  if (p.contains("payload") && !p["payload"].is_boolean()) throw ProjectError(what + ": payload must be true or false");
  out["payload"] = p.value("payload", false);
  return out;
}

Json normalised_segment(const Json& g, std::size_t k) {
  const std::string what = fmt::format("segment {}", k + 1);
  if (!g.is_object() || !g.contains("kind") || !g["kind"].is_string()) throw ProjectError(what + ": expected {kind: ...}");
  const std::string kind = g["kind"].get<std::string>();
  if (kind == "move") {
    if (g.contains("relative") && !g["relative"].is_boolean()) throw ProjectError(what + ": relative must be true or false");
    return {{"kind", kind}, {"deg", number(g.value("deg", Json(0.0)), what + " deg")}, {"relative", g.value("relative", false)}};
  }
  if (kind == "dwell") return {{"kind", kind}, {"s", number(g.value("s", Json(0.0)), what + " s")}};
  if (kind == "grip" || kind == "release") return {{"kind", kind}};
  throw ProjectError(fmt::format("{}: kind '{}' is not one of move, dwell, grip, release", what, kind));
}

std::string yaml_num(double v) { return fmt::format("{}", v); }

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
      {"mesh", {"mass_kg", "scale"}}, // plus its STL "file" (mesh_upload.hpp)
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
  if (state.contains("mode")) {
    if (state["mode"] != "single" && state["mode"] != "cycle") {
      throw ProjectError(fmt::format("mode: expected single or cycle, got {}", state["mode"].dump()));
    }
    s["mode"] = state["mode"];
  }
  if (state.contains("segments")) {
    if (!state["segments"].is_array()) throw ProjectError("segments: expected a list");
    s["segments"] = Json::array();
    for (std::size_t k = 0; k < state["segments"].size(); ++k) s["segments"].push_back(normalised_segment(state["segments"][k], k));
  }
  if (state.contains("uncertainty")) {
    if (!state["uncertainty"].is_boolean()) throw ProjectError("uncertainty: expected true or false");
    s["uncertainty"] = state["uncertainty"];
  }
  return s;
}

std::string parts_yaml(const Json& parts, const std::string& indent, double mass_scale) {
  std::string o = indent + "parts:\n";
  for (const Json& p : parts) {
    const ShapeKeys& keys = shape_keys(p["shape"].get<std::string>(), "part");
    o += indent + "  - name: " + yaml_text(p["name"].get<std::string>()) + "\n";
    o += fmt::format("{}    {}: {{", indent, keys.shape);
    if (p.contains("file")) o += "file: " + yaml_text(p["file"].get<std::string>()) + ", ";
    for (std::size_t i = 0; i < keys.keys.size(); ++i) {
      double v = p[keys.keys[i]].get<double>();
      if (i == 0) v *= mass_scale; // mass_kg
      o += fmt::format("{}{}: {}", i ? ", " : "", keys.keys[i], yaml_num(v));
    }
    o += "}\n";
    o += fmt::format("{}    at_m: [{}, {}, {}]\n", indent, yaml_num(p["at_m"][0]), yaml_num(p["at_m"][1]), yaml_num(p["at_m"][2]));
    o += fmt::format("{}    rpy_deg: [{}, {}, {}]\n", indent, yaml_num(p["rpy_deg"][0]), yaml_num(p["rpy_deg"][1]), yaml_num(p["rpy_deg"][2]));
  }
  return o;
}

std::string load_yaml(const Json& state_in, double mass_scale) {
  const Json s = normalised_state(state_in);
  std::string o = "name: " + yaml_text(s["name"].get<std::string>()) + "\n";
  o += s["parts"].empty() ? "load: {inertia_gcm2: 0}\n" : "load:\n" + parts_yaml(s["parts"], "  ", mass_scale);
  o += fmt::format("mounting: {{tilt_deg: {}}}\n", yaml_num(s["mounting_tilt_deg"].get<double>()));
  return o;
}

std::string project_yaml(const Json& state_in) {
  const Json s = normalised_state(state_in);
  const bool cycle = s["mode"] == "cycle";
  std::string o;
  o += "# sreh-twin studio project (docs/studio.md): `sreh-twin studio THIS_FILE` reopens it;\n";
  o += "# the same answer on the command line: " + size_command_line(s, "THIS_FILE") + "\n";
  o += cycle ? cycle_file_yaml(s) : load_yaml(s);
  o += "studio:\n";
  o += fmt::format("  mode: {}\n  uncertainty: {}\n", s["mode"].get<std::string>(), s["uncertainty"].get<bool>());
  std::string payload;
  for (std::size_t k = 0; k < s["parts"].size(); ++k) {
    if (s["parts"][k]["payload"].get<bool>()) payload += fmt::format("{}{}", payload.empty() ? "" : ", ", k + 1);
  }
  if (!payload.empty()) o += "  payload_parts: [" + payload + "]\n";
  for (const char* key : {"angle_deg", "dwell_s", "tolerance_deg"}) o += fmt::format("  {}: {}\n", key, yaml_num(s[key].get<double>()));
  o += fmt::format("  target: {}\n", s["target"].get<std::string>());
  for (const char* key : {"target_ms", "voltage_V", "ambient_C"}) o += fmt::format("  {}: {}\n", key, yaml_num(s[key].get<double>()));
  if (!s["set"].is_null()) {
    o += fmt::format("  set: {{speed_dps: {}, accel_pct: {}, jerk_pct: {}}}\n", yaml_num(s["set"]["speed_dps"].get<double>()),
                     yaml_num(s["set"]["accel_pct"].get<double>()), yaml_num(s["set"]["jerk_pct"].get<double>()));
  }
  return o;
}

namespace {

// A mesh part's STL as the state holds it: absolute (the load parser
// resolves a relative one against the file's folder, so does this).
std::string mesh_path(const YAML::Node& dims, const std::string& file) {
  namespace fs = std::filesystem;
  const fs::path given(dims["file"].as<std::string>());
  const fs::path folder = fs::path(file).parent_path();
  const fs::path base = folder.empty() ? fs::current_path() : fs::absolute(folder);
  return (given.is_absolute() ? given : base / given).lexically_normal().string();
}

// The parts of a load node ({parts: [...]}, or no load) as the state holds them.
Json parts_of(const YAML::Node& load, const std::string& file) {
  Json parts = Json::array();
  if (load.IsMap() && load["parts"]) {
    for (const YAML::Node& part : load["parts"]) {
      Json p = {{"name", part["name"] ? part["name"].as<std::string>() : std::string()}};
      const ShapeKeys* found = nullptr;
      for (const ShapeKeys& s : part_shapes()) {
        if (part[s.shape]) found = &s;
      }
      if (!found) yaml_fail(part, file, "the studio builds loads of disk, ring, box, cylinder, sphere, point and mesh parts only");
      p["shape"] = found->shape;
      const YAML::Node dims = part[found->shape];
      if (std::string(found->shape) == "mesh") {
        if (!dims["mass_kg"]) yaml_fail(dims, file, "the studio takes a mesh's mass_kg, not its density_kg_m3");
        p["file"] = mesh_path(dims, file);
      }
      for (const char* key : found->keys) {
        // The parser checked the part: only a thickness (default 0.01 m,
        // twin/specs.hpp) or a mesh's scale (1) may be left out.
        const double left_out = std::string(key) == "scale" ? MeshPart{}.scale : DiskLoad{}.thickness_m;
        p[key] = dims[key] ? Json(yaml_number(dims[key], file, key)) : Json(left_out);
      }
      for (const char* key : {"at_m", "rpy_deg"}) {
        Json v = Json::array({0.0, 0.0, 0.0});
        if (part[key]) {
          for (std::size_t i = 0; i < 3; ++i) v[i] = yaml_number(part[key][i], file, key);
        }
        p[key] = v;
      }
      parts.push_back(p);
    }
  } else if (!(load.IsMap() && load["inertia_gcm2"] && load["inertia_gcm2"].as<double>() == 0.0)) {
    yaml_fail(load, file, "the studio builds loads from parts (load: {parts: [...]}); this load is one shape or a file");
  }
  return parts;
}

// A cycle file's segments as the studio's: a load change to more parts than
// the cycle starts with is a grip, else a release; every part is in the
// first grip's load (cycle_file_yaml writes it so).
void read_cycle(const YAML::Node& root, const std::string& file, Json& state) {
  const std::size_t base = state["parts"].size();
  state["mode"] = "cycle";
  state["segments"] = Json::array();
  bool gripped = false;
  for (const YAML::Node& g : root["segments"]) {
    if (g["move_deg"]) {
      state["segments"].push_back({{"kind", "move"}, {"deg", yaml_number(g["move_deg"], file, "move_deg")},
                                   {"relative", g["relative"] && g["relative"].as<bool>()}});
    } else if (g["dwell_s"]) {
      state["segments"].push_back({{"kind", "dwell"}, {"s", yaml_number(g["dwell_s"], file, "dwell_s")}});
    } else {
      const Json parts = parts_of(g["load"], file);
      const bool grip = parts.size() > base;
      if (grip && !gripped) state["parts"] = parts;
      gripped = gripped || grip;
      state["segments"].push_back({{"kind", grip ? "grip" : "release"}});
    }
  }
  if (root["supply"] && root["supply"]["voltage_V"]) state["voltage_V"] = yaml_number(root["supply"]["voltage_V"], file, "supply.voltage_V");
  if (root["ambient_C"]) state["ambient_C"] = yaml_number(root["ambient_C"], file, "ambient_C");
  if (root["tolerance_deg"]) state["tolerance_deg"] = yaml_number(root["tolerance_deg"], file, "tolerance_deg");
}

} // namespace

Json state_from_project_text(const std::string& text, const std::string& file) {
  const YAML::Node root = detail::load_yaml_safely(text, file, Limits{});
  const bool cycle = root.IsMap() && root["segments"];
  // The file as `size --load` (a load file) or `size --cycle` (a cycle file)
  // reads it: same keys, limits, errors.
  std::optional<double> tilt;
  const std::string base_dir = std::filesystem::path(file).parent_path().string(); // as parse_load_file
  try {
    if (cycle) tilt = sizing::parse_cycle_text(text, file, base_dir).world.mounting_tilt_deg;
    else tilt = parse_load_text(text, file, base_dir).mounting_tilt_deg;
  } catch (const ScenarioError& e) {
    throw ProjectError(e.what());
  } catch (const sizing::SizingInputError& e) {
    throw ProjectError(e.what());
  }
  Json state = {{"parts", parts_of(root["load"], file)}};
  if (root["name"]) state["name"] = root["name"].as<std::string>();
  if (cycle) read_cycle(root, file, state);
  if (tilt) state["mounting_tilt_deg"] = *tilt;
  if (const YAML::Node st = root["studio"]) {
    if (!st.IsMap()) yaml_fail(st, file, "studio: expected a map");
    for (const auto& kv : st) {
      const std::string key = kv.first.as<std::string>();
      if (key == "target" || key == "mode") state[key] = kv.second.as<std::string>();
      else if (key == "uncertainty") state[key] = kv.second.as<bool>();
      else if (key == "payload_parts") {
        for (const YAML::Node& k : kv.second) {
          const double n = yaml_number(k, file, "studio.payload_parts");
          if (n < 1 || n > static_cast<double>(state["parts"].size()) || n != std::floor(n)) {
            yaml_fail(k, file, fmt::format("studio.payload_parts: {} is not a part number 1 .. {}", n, state["parts"].size()));
          }
          state["parts"][static_cast<std::size_t>(n) - 1]["payload"] = true;
        }
      } else if (key == "set") {
        Json set;
        for (const char* k : kSetKeys) {
          if (kv.second[k]) set[k] = yaml_number(kv.second[k], file, std::string("studio.set.") + k);
        }
        state["set"] = set;
      } else if (key == "angle_deg" || key == "dwell_s" || key == "tolerance_deg" || key == "target_ms" ||
                 key == "voltage_V" || key == "ambient_C") {
        state[key] = yaml_number(kv.second, file, "studio." + key);
      } else {
        yaml_fail(kv.first, file, "studio." + key + ": unknown key (mode, uncertainty, payload_parts, angle_deg, dwell_s, "
                                  "tolerance_deg, target, target_ms, voltage_V, ambient_C, set)");
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
  if (normalised_state(state)["mode"] == "cycle") return "sreh-twin size --cycle " + load_file;
  const sizing::SizeOptions o = size_options(state);
  std::string c = fmt::format("sreh-twin size --load {} --angle-deg {} --voltage-V {} --dwell-s {} --tolerance-deg {} --ambient-C {}",
                              load_file, yaml_num(*o.angle_deg), yaml_num(o.voltage_V), yaml_num(o.dwell_s), yaml_num(o.tolerance_deg),
                              yaml_num(o.ambient_C));
  if (o.max_positioning_ms) c += " --max-positioning-ms " + yaml_num(*o.max_positioning_ms);
  if (o.max_cycle_ms) c += " --max-cycle-ms " + yaml_num(*o.max_cycle_ms);
  if (o.speed_dps) c += fmt::format(" --speed-dps {} --accel-pct {} --jerk-pct {}", yaml_num(*o.speed_dps), yaml_num(*o.accel_pct), yaml_num(*o.jerk_pct));
  return c;
}

} // namespace sreh::studio
