#include "scenarios/load_parser.hpp"

#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "scenarios/load_file.hpp"
#include "twin/load_builder.hpp"

namespace sreh::detail {
namespace {

const std::vector<std::string_view> kPartShapes = {"disk", "ring", "box", "cylinder", "sphere", "point", "mesh", "mjcf"};
const std::vector<std::string_view> kSingleOnly = {"arm", "inertia_gcm2", "none"};
constexpr double kMaxLength_m = 10.0;
constexpr double kMaxMass_kg = 100.0;
constexpr int kMaxFileDepth = 4;

class LoadReader {
 public:
  LoadReader(const YamlReader& r, const FileResolver& resolve) : r_(r), resolve_(resolve) {}

  LoadSpec parse(const YAML::Node& n) {
    std::vector<std::string_view> keys = kPartShapes;
    keys.insert(keys.end(), kSingleOnly.begin(), kSingleOnly.end());
    for (std::string_view k : {"parts", "at_m", "rpy_deg", "file"}) keys.push_back(k);
    r_.check_map(n, "load", keys);
    if (n["file"]) {
      if (n.size() != 1) r_.fail(n, "load: file: LOAD.yaml stands alone");
      return from_file(n["file"]);
    }
    if (n["parts"]) {
      if (n.size() != 1) r_.fail(n, "load: parts: [...] stands alone (each part has its own shape, at_m and rpy_deg)");
      return parts(n["parts"]);
    }
    const int placed = (n["at_m"] ? 1 : 0) + (n["rpy_deg"] ? 1 : 0);
    if (n.size() - static_cast<std::size_t>(placed) != 1) {
      r_.fail(n, "load: give exactly one of disk, ring, box, cylinder, sphere, point, mesh, mjcf, arm, inertia_gcm2, none "
                 "(or parts: [...] for an assembly)");
    }
    std::string kind;
    for (const auto& kv : n) {
      const std::string k = kv.first.Scalar();
      if (k != "at_m" && k != "rpy_deg") kind = k;
    }
    const YAML::Node v = n[kind];
    const std::string what = "load." + kind;
    const bool legacy = kind == "disk" || kind == "ring" || kind == "box" || kind == "mjcf";
    if (placed == 0 && legacy) { // issue 5's forms, built as before: on the mounting face
      const PartShape s = shape(kind, v, what);
      return std::visit([](const auto& x) -> LoadSpec {
        if constexpr (std::is_constructible_v<LoadSpec, decltype(x)>) return x;
        else return NoLoad{};
      }, s);
    }
    if (kind == "arm" || kind == "inertia_gcm2" || kind == "none") {
      if (placed != 0) r_.fail(n, fmt::format("load: at_m and rpy_deg place a part shape, not '{}'", kind));
      return single_only(kind, v, what);
    }
    AssemblyLoad a;
    a.origin = r_.loc(n).str();
    a.parts.push_back(part_of(n, kind, "load"));
    return a;
  }

 private:
  // `load: {file: models/loads/x.yaml}`: a load file's load (its mounting:
  // is the file's own business; the scenario's mounting: holds), with that
  // file's own lines in errors.
  LoadSpec from_file(const YAML::Node& f) {
    static thread_local int depth = 0;
    if (depth >= kMaxFileDepth) r_.fail(f, "load.file: load files name each other more than 4 deep");
    const std::string path = resolve_(f, "load.file");
    ++depth;
    try {
      LoadSpec load = parse_load_file(path).load;
      --depth;
      return load;
    } catch (...) {
      --depth;
      throw;
    }
  }

  LoadSpec single_only(const std::string& kind, const YAML::Node& v, const std::string& what) {
    if (kind == "arm") {
      r_.check_map(v, what, {"mass_kg", "radius_m", "arm_mass_kg"});
      ArmLoad a{mass(v, what), length(v, what, "radius_m", 0.0)};
      if (v["arm_mass_kg"]) a.arm_mass_kg = r_.number(v["arm_mass_kg"], what + ".arm_mass_kg", 0.0, kMaxMass_kg);
      return a;
    }
    if (kind == "none") {
      if (!v.IsNull() && !(v.IsScalar() && r_.boolean(v, what))) r_.fail(v, "load.none: write 'none: true' or leave load out");
      return NoLoad{};
    }
    // inertia_gcm2; the manual's parameter range is 0..15000 (6.2, 64.4), the physics allows more.
    const double j = r_.number(v, what, 0.0, 1e6);
    if (j > 0 && j < kMinInertiaGcm2) {
      r_.fail(v, fmt::format("{}: {} is above 0 but below {} g cm^2, too small to model; use 0 for no load", what,
                             v.Scalar(), kMinInertiaGcm2));
    }
    return InertiaLoad{j};
  }

  AssemblyLoad parts(const YAML::Node& list) {
    if (!list.IsSequence() || list.size() == 0) {
      r_.fail(list, "load.parts: expected a list of parts, e.g. [{disk: {mass_kg: 0.5, radius_m: 0.04}, at_m: [0, 0, 0.005]}]");
    }
    AssemblyLoad a;
    a.origin = r_.loc(list).str();
    for (std::size_t i = 0; i < list.size(); ++i) {
      const YAML::Node p = list[i];
      const std::string what = fmt::format("load.parts[{}]", i);
      std::vector<std::string_view> keys = kPartShapes;
      keys.push_back("at_m");
      keys.push_back("rpy_deg");
      keys.push_back("name");
      r_.check_map(p, what, keys);
      std::string kind;
      int shapes = 0;
      for (const auto& kv : p) {
        const std::string k = kv.first.Scalar();
        if (k != "at_m" && k != "rpy_deg" && k != "name") { kind = k; ++shapes; }
      }
      if (shapes != 1) {
        r_.fail(p, what + ": give exactly one shape of disk, ring, box, cylinder, sphere, point, mesh, mjcf, plus at_m and rpy_deg");
      }
      a.parts.push_back(part_of(p, kind, what));
      if (p["name"]) a.parts.back().name = r_.text(p["name"], what + ".name");
    }
    return a;
  }

  LoadPart part_of(const YAML::Node& p, const std::string& kind, const std::string& what) {
    LoadPart part;
    part.shape = shape(kind, p[kind], what + "." + kind);
    if (p["at_m"]) part.at_m = triple(p["at_m"], what + ".at_m", -kMaxLength_m, kMaxLength_m);
    if (p["rpy_deg"]) part.rpy_deg = triple(p["rpy_deg"], what + ".rpy_deg", -360.0, 360.0);
    part.origin = r_.loc(p).str() + ": " + what;
    part_locs_.push_back({part.origin, r_.loc(p), what});
    return part;
  }

  std::array<double, 3> triple(const YAML::Node& n, const std::string& what, double lo, double hi) {
    if (!n.IsSequence() || n.size() != 3) r_.fail(n, what + ": expected [x, y, z]");
    return {r_.number(n[0], what + "[0]", lo, hi), r_.number(n[1], what + "[1]", lo, hi), r_.number(n[2], what + "[2]", lo, hi)};
  }

  double mass(const YAML::Node& m, const std::string& what) {
    return r_.number(r_.require(m, "mass_kg", what), what + ".mass_kg", 1e-6, kMaxMass_kg);
  }
  double length(const YAML::Node& m, const std::string& what, const char* key, double min) {
    return r_.number(r_.require(m, key, what), fmt::format("{}.{}", what, key), min, kMaxLength_m);
  }

  PartShape shape(const std::string& kind, const YAML::Node& v, const std::string& what) {
    if (kind == "disk") {
      r_.check_map(v, what, {"mass_kg", "radius_m", "thickness_m"});
      DiskLoad d{mass(v, what), length(v, what, "radius_m", 1e-6)};
      if (v["thickness_m"]) d.thickness_m = length(v, what, "thickness_m", 1e-6);
      return d;
    }
    if (kind == "ring") {
      r_.check_map(v, what, {"mass_kg", "inner_radius_m", "outer_radius_m", "thickness_m"});
      RingLoad g{mass(v, what), length(v, what, "inner_radius_m", 0.0), length(v, what, "outer_radius_m", 1e-6)};
      if (g.inner_radius_m >= g.outer_radius_m) r_.fail(v["inner_radius_m"], what + ": inner_radius_m must be below outer_radius_m");
      if (v["thickness_m"]) g.thickness_m = length(v, what, "thickness_m", 1e-6);
      return g;
    }
    if (kind == "box") {
      r_.check_map(v, what, {"mass_kg", "x_m", "y_m", "z_m"});
      return BoxLoad{mass(v, what), length(v, what, "x_m", 1e-6), length(v, what, "y_m", 1e-6), length(v, what, "z_m", 1e-6)};
    }
    if (kind == "cylinder") {
      r_.check_map(v, what, {"mass_kg", "radius_m", "length_m"});
      return CylinderPart{mass(v, what), length(v, what, "radius_m", 1e-6), length(v, what, "length_m", 1e-6)};
    }
    if (kind == "sphere") {
      r_.check_map(v, what, {"mass_kg", "radius_m"});
      return SpherePart{mass(v, what), length(v, what, "radius_m", 1e-6)};
    }
    if (kind == "point") {
      r_.check_map(v, what, {"mass_kg"});
      return PointPart{mass(v, what)};
    }
    if (kind == "mesh") {
      r_.check_map(v, what, {"file", "mass_kg", "density_kg_m3", "scale"});
      MeshPart m;
      m.path = resolve_(r_.require(v, "file", what), what + ".file");
      if (v["mass_kg"] && v["density_kg_m3"]) r_.fail(v, what + ": give mass_kg or density_kg_m3, not both");
      if (v["mass_kg"]) m.mass_kg = mass(v, what);
      else if (v["density_kg_m3"]) m.density_kg_m3 = r_.number(v["density_kg_m3"], what + ".density_kg_m3", 1.0, 1e5);
      else r_.fail(v, what + ": give mass_kg or density_kg_m3 (the mesh's volume gives the other)");
      if (v["scale"]) m.scale = r_.number(v["scale"], what + ".scale", 1e-6, 1e3);
      return m;
    }
    // mjcf: a file, relative to the naming file's folder, or models/... from the project root.
    return MjcfLoad{resolve_(v, what)};
  }

  const YamlReader& r_;
  const FileResolver& resolve_;

 public:
  struct PartLoc { std::string origin; SourceLoc loc; std::string what; };
  std::vector<PartLoc> part_locs_;
};

// The twin's refusal at the line it belongs to: a part's own, or the load's.
[[noreturn]] void fail_at_origin(const YamlReader& r, const YAML::Node& n, const LoadSpec& load,
                                 const std::vector<LoadReader::PartLoc>& parts, std::string why) {
  for (const auto& p : parts) {
    if (why.rfind(p.origin + ": ", 0) == 0) r.fail(p.loc, p.what + ": " + why.substr(p.origin.size() + 2));
  }
  if (const auto* a = std::get_if<AssemblyLoad>(&load); a && why.rfind(a->origin + ": ", 0) == 0) {
    why.erase(0, a->origin.size() + 2);
  }
  r.fail(n, "load: " + why);
}

} // namespace

LoadSpec parse_load_value(const YamlReader& r, const YAML::Node& node, const FileResolver& resolve) {
  LoadReader reader(r, resolve);
  LoadSpec load = reader.parse(node);
  if (std::holds_alternative<NoLoad>(load)) return load;
  try {
    (void)check_load(load); // the twin's own checks: limit, files, MuJoCo
  } catch (const std::invalid_argument& e) {
    fail_at_origin(r, node, load, reader.part_locs_, e.what());
  } catch (const std::runtime_error& e) { // a MuJoCo warning on numbers it cannot use (A-TWIN-14)
    fail_at_origin(r, node, load, reader.part_locs_, e.what());
  }
  return load;
}

} // namespace sreh::detail
