#include "twin/load_builder.hpp"
#include "twin/models_dir.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <regex>
#include <stdexcept>

#include "device_logic/parameter_ids.hpp"
#include "device_logic/units.hpp"
#include "twin/load_parts.hpp"
#include "twin/mjcf_load.hpp"
#include "twin/model_cache.hpp"
#include "twin/model_lean.hpp"

namespace sreh {
namespace {

// Assumptions for loads given only by numbers (docs/assumptions/twin.md).
constexpr double kSteelDensity_kg_m3 = 7850.0;      // A-TWIN-5: InertiaLoad is a steel disk ...
constexpr double kInertiaDiskThickness_m = 0.010;   // ... 10 mm thick
constexpr double kArmBarHalfSection_m = 0.005;      // A-TWIN-6: arm drawn as a 10 x 10 mm bar
constexpr int kRingSegments = 32;                   // ring drawn from box segments (visual only)
// A-TWIN-8: MuJoCo's sums carry rounding (0.15 kg at 0.1 m computes
// 15000.00001): the limit holds within this relative tolerance.
constexpr double kLoadLimitRelativeTolerance = 1e-9;

constexpr const char* kLoadMarker = "<!-- sreh:load -->";
constexpr const char* kWorldMarker = "<!-- sreh:world -->";
constexpr const char* kAssetMarker = "<!-- sreh:asset -->";

std::string num(double v) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v); // shortest round-trip form
  return std::string(buf, res.ptr);
}

void require_positive(double v, const char* what, const std::string& origin) {
  if (!(v > 0.0) || !std::isfinite(v)) {
    throw std::invalid_argument(origin + ": " + what + " must be positive and finite, got " + num(v));
  }
}

void require_non_negative(double v, const char* what, const std::string& origin) {
  if (!(v >= 0.0) || !std::isfinite(v)) {
    throw std::invalid_argument(origin + ": " + what + " must be >= 0 and finite, got " + num(v));
  }
}

std::string disk_xml(const DiskLoad& l, const std::string& origin) {
  require_positive(l.mass_kg, "disk mass_kg", origin);
  require_positive(l.radius_m, "disk radius_m", origin);
  require_positive(l.thickness_m, "disk thickness_m", origin);
  const double h = l.thickness_m / 2;
  // MuJoCo's solid cylinder: Izz = m r^2 / 2.
  return "<body name=\"load\"><geom name=\"load_disk\" type=\"cylinder\" size=\"" + num(l.radius_m) + " " + num(h) +
         "\" pos=\"0 0 " + num(h) + "\" mass=\"" + num(l.mass_kg) + "\" material=\"load_alu\"/></body>";
}

std::string ring_xml(const RingLoad& l, const std::string& origin) {
  require_positive(l.mass_kg, "ring mass_kg", origin);
  require_non_negative(l.inner_radius_m, "ring inner_radius_m", origin);
  require_positive(l.outer_radius_m, "ring outer_radius_m", origin);
  require_positive(l.thickness_m, "ring thickness_m", origin);
  if (!(l.inner_radius_m < l.outer_radius_m)) {
    throw std::invalid_argument(origin + ": ring inner_radius_m (" + num(l.inner_radius_m) +
                                ") must be below outer_radius_m (" + num(l.outer_radius_m) + ")");
  }
  const double ri2 = l.inner_radius_m * l.inner_radius_m;
  const double ro2 = l.outer_radius_m * l.outer_radius_m;
  const double t = l.thickness_m;
  const double izz = l.mass_kg * (ri2 + ro2) / 2;                  // hollow cylinder
  const double ixx = l.mass_kg * (3 * (ri2 + ro2) + t * t) / 12;
  // MuJoCo has no hollow primitive: exact inertial, massless box segments to show it.
  std::string xml = "<body name=\"load\"><inertial pos=\"0 0 " + num(t / 2) + "\" mass=\"" + num(l.mass_kg) +
                    "\" diaginertia=\"" + num(ixx) + " " + num(ixx) + " " + num(izz) + "\"/>";
  const double r_mid = (l.inner_radius_m + l.outer_radius_m) / 2;
  const double half_radial = (l.outer_radius_m - l.inner_radius_m) / 2;
  const double half_tangential = kPi * r_mid / kRingSegments * 1.02;
  for (int k = 0; k < kRingSegments; ++k) {
    const double a = 2 * kPi * k / kRingSegments;
    xml += "<geom name=\"load_ring_" + std::to_string(k) + "\" type=\"box\" size=\"" + num(half_radial) + " " +
           num(half_tangential) + " " + num(t / 2) + "\" pos=\"" + num(r_mid * std::cos(a)) + " " +
           num(r_mid * std::sin(a)) + " " + num(t / 2) + "\" euler=\"0 0 " + num(a) +
           "\" mass=\"0\" material=\"load_alu\"/>";
  }
  return xml + "</body>";
}

std::string box_xml(const BoxLoad& l, const std::string& origin) {
  require_positive(l.mass_kg, "box mass_kg", origin);
  require_positive(l.x_m, "box x_m", origin);
  require_positive(l.y_m, "box y_m", origin);
  require_positive(l.z_m, "box z_m", origin);
  // MuJoCo's solid box: Izz = m (x^2 + y^2) / 12, centred on the axis.
  return "<body name=\"load\"><geom name=\"load_box\" type=\"box\" size=\"" + num(l.x_m / 2) + " " + num(l.y_m / 2) +
         " " + num(l.z_m / 2) + "\" pos=\"0 0 " + num(l.z_m / 2) + "\" mass=\"" + num(l.mass_kg) +
         "\" material=\"load_alu\"/></body>";
}

std::string arm_xml(const ArmLoad& l, const std::string& origin) {
  require_positive(l.mass_kg, "arm mass_kg", origin);
  require_positive(l.radius_m, "arm radius_m", origin);
  require_non_negative(l.arm_mass_kg, "arm arm_mass_kg", origin);
  const double r = l.radius_m;
  const double z = kArmBarHalfSection_m;
  std::string xml = "<body name=\"load\">";
  if (l.arm_mass_kg > 0) {
    // Thin rod along x from the axis to r: about its centre m r^2 / 12;
    // MuJoCo adds m (r/2)^2, so m r^2 / 3 about the axis.
    const double i_end = l.arm_mass_kg * r * r / 12;
    xml += "<inertial pos=\"" + num(r / 2) + " 0 " + num(z) + "\" mass=\"" + num(l.arm_mass_kg) +
           "\" diaginertia=\"1e-12 " + num(i_end) + " " + num(i_end) + "\"/>";
  }
  xml += "<geom name=\"load_arm\" type=\"box\" size=\"" + num(r / 2) + " " + num(kArmBarHalfSection_m) + " " + num(z) +
         "\" pos=\"" + num(r / 2) + " 0 " + num(z) + "\" mass=\"0\" material=\"load_alu\"/>";
  // The point mass: exact inertial, a steel sphere of that mass to show it.
  const double sphere_r = std::cbrt(3 * l.mass_kg / (4 * kPi * kSteelDensity_kg_m3));
  xml += "<body name=\"load_tip\" pos=\"" + num(r) + " 0 " + num(2 * z + sphere_r) + "\"><inertial pos=\"0 0 0\" mass=\"" +
         num(l.mass_kg) + "\" diaginertia=\"1e-12 1e-12 1e-12\"/><geom name=\"load_tip\" type=\"sphere\" size=\"" +
         num(sphere_r) + "\" mass=\"0\" material=\"load_steel\"/></body>";
  return xml + "</body>";
}

std::string inertia_xml(const InertiaLoad& l, const std::string& origin) {
  require_non_negative(l.inertia_gcm2, "inertia_gcm2", origin);
  if (l.inertia_gcm2 > 0 && l.inertia_gcm2 < kMinInertiaGcm2) {
    // Below this the disk's radius and mass underflow (1e-320 gave a NaN mass).
    throw std::invalid_argument(origin + ": inertia_gcm2 " + num(l.inertia_gcm2) + " is above 0 but below " +
                                num(kMinInertiaGcm2) + " g cm^2, too small to model; use 0 for no load");
  }
  if (l.inertia_gcm2 == 0) {
    return {};
  }
  // A steel disk of that inertia: J = rho pi t r^4 / 2.
  const double j = gcm2_to_kgm2(l.inertia_gcm2);
  const double t = kInertiaDiskThickness_m;
  const double r = std::pow(2 * j / (kSteelDensity_kg_m3 * kPi * t), 0.25);
  const double mass = 2 * j / (r * r);
  return "<body name=\"load\"><inertial pos=\"0 0 " + num(t / 2) + "\" mass=\"" + num(mass) + "\" diaginertia=\"" +
         num(mass * (3 * r * r + t * t) / 12) + " " + num(mass * (3 * r * r + t * t) / 12) + " " + num(j) +
         "\"/><geom name=\"load_disk\" type=\"cylinder\" size=\"" + num(r) + " " + num(t / 2) + "\" pos=\"0 0 " +
         num(t / 2) + "\" mass=\"0\" material=\"load_steel\"/></body>";
}

void replace_marker(std::string& xml, const char* marker, const std::string& content, const std::string& module_path) {
  const std::size_t at = xml.find(marker);
  if (at == std::string::npos) {
    throw std::invalid_argument(module_path + ": marker " + marker + " missing");
  }
  xml.replace(at, std::string(marker).size(), content);
}

std::string hard_stops_xml(const std::vector<HardStop>& stops) {
  // Geometry of the flange's stop_lug in models/sreh50.xml and the stop
  // post: lug tangential half width 3 mm, post 4 mm. The post lies beyond the
  // stop angle as seen from 0 deg, so the lug's face meets it flush exactly
  // at angle_deg (positive motion stops there for angle_deg >= 0, negative
  // motion for angle_deg < 0). Flange joint axis is -z: a flange angle q is a
  // rotation by -q about world z.
  constexpr double kLugHalfWidth_m = 0.003;
  constexpr double kPostHalfWidth_m = 0.004;
  std::string xml;
  for (std::size_t i = 0; i < stops.size(); ++i) {
    const double q = deg_to_rad(stops[i].angle_deg);
    if (!std::isfinite(q)) {
      throw std::invalid_argument("hard stop " + std::to_string(i) + ": angle_deg must be finite");
    }
    const double side = stops[i].angle_deg >= 0 ? -1.0 : 1.0;
    const std::string name = "hard_stop_" + std::to_string(i);
    xml += "<body name=\"" + name + "\" euler=\"0 0 " + num(-q) + "\"><geom name=\"" + name +
           "\" type=\"box\" size=\"0.006 " + num(kPostHalfWidth_m) + " 0.032\" pos=\"0.040 " +
           num(side * (kLugHalfWidth_m + kPostHalfWidth_m)) + " 0.032\" conaffinity=\"2\" material=\"stop\"/></body>";
  }
  return xml;
}

} // namespace

std::string default_module_model_path() { return models_dir() + "/sreh50.xml"; }

std::string describe_load(const LoadSpec& load) {
  struct Describe {
    std::string operator()(const NoLoad&) const { return "no load"; }
    std::string operator()(const DiskLoad& l) const {
      return "disk load (mass_kg " + num(l.mass_kg) + ", radius_m " + num(l.radius_m) + ", thickness_m " + num(l.thickness_m) + ")";
    }
    std::string operator()(const RingLoad& l) const {
      return "ring load (mass_kg " + num(l.mass_kg) + ", inner_radius_m " + num(l.inner_radius_m) + ", outer_radius_m " +
             num(l.outer_radius_m) + ", thickness_m " + num(l.thickness_m) + ")";
    }
    std::string operator()(const BoxLoad& l) const {
      return "box load (mass_kg " + num(l.mass_kg) + ", x_m " + num(l.x_m) + ", y_m " + num(l.y_m) + ", z_m " + num(l.z_m) + ")";
    }
    std::string operator()(const ArmLoad& l) const {
      return "arm load (mass_kg " + num(l.mass_kg) + ", radius_m " + num(l.radius_m) + ", arm_mass_kg " + num(l.arm_mass_kg) + ")";
    }
    std::string operator()(const InertiaLoad& l) const { return "inertia load (" + num(l.inertia_gcm2) + " g cm^2)"; }
    std::string operator()(const MjcfLoad& l) const { return l.path; }
    std::string operator()(const AssemblyLoad& l) const {
      return l.origin.empty() ? "assembly load (" + std::to_string(l.parts.size()) + " parts)" : l.origin;
    }
  };
  return std::visit(Describe{}, load);
}

std::vector<std::string> load_input_files(const LoadSpec& load) {
  std::vector<std::string> files;
  if (const auto* m = std::get_if<MjcfLoad>(&load)) files.push_back(m->path);
  if (const auto* a = std::get_if<AssemblyLoad>(&load)) {
    for (const LoadPart& p : a->parts) {
      if (const auto* f = std::get_if<MjcfLoad>(&p.shape)) files.push_back(f->path);
      if (const auto* f = std::get_if<MeshPart>(&p.shape)) files.push_back(f->path);
    }
  }
  return files;
}

ComposedModel compose_model(const LoadSpec& load, const std::vector<HardStop>& hard_stops,
                            const std::string& module_model_path) {
  ComposedModel composed;
  std::string& xml = composed.xml;
  xml = read_text_file(module_model_path);
  std::string module_assets;
  if (!inner_of(xml, "asset", module_assets)) {
    throw std::invalid_argument(module_model_path + ": no <asset> section");
  }
  const std::string origin = describe_load(load);
  std::string body;
  std::string assets;
  if (const auto* l = std::get_if<DiskLoad>(&load)) body = disk_xml(*l, origin);
  else if (const auto* r = std::get_if<RingLoad>(&load)) body = ring_xml(*r, origin);
  else if (const auto* b = std::get_if<BoxLoad>(&load)) body = box_xml(*b, origin);
  else if (const auto* a = std::get_if<ArmLoad>(&load)) body = arm_xml(*a, origin);
  else if (const auto* i = std::get_if<InertiaLoad>(&load)) body = inertia_xml(*i, origin);
  else if (const auto* f = std::get_if<MjcfLoad>(&load)) {
    // Its own namespace (issue 28): the user's names cannot clash with the module's.
    LoadXml parts = mjcf_load_xml(f->path, module_assets, "load/");
    body = std::move(parts.body);
    assets = std::move(parts.assets);
    composed.files = std::move(parts.files);
  } else if (const auto* s = std::get_if<AssemblyLoad>(&load)) {
    LoadXml parts = assembly_xml(*s, module_assets);
    body = std::move(parts.body);
    assets = std::move(parts.assets);
    composed.files = std::move(parts.files);
  }
  replace_marker(xml, kAssetMarker, assets, module_model_path);
  replace_marker(xml, kLoadMarker, body, module_model_path);
  replace_marker(xml, kWorldMarker, hard_stops_xml(hard_stops), module_model_path);
  return composed;
}

std::string compose_model_xml(const LoadSpec& load, const std::vector<HardStop>& hard_stops,
                              const std::string& module_model_path) {
  return compose_model(load, hard_stops, module_model_path).xml;
}

std::string round_gcm2(double gcm2) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.1f", gcm2);
  return buf;
}

double max_load_gcm2() { return display_max(param::MotionSet(0).load); }

bool within_load_limit(double load_gcm2) { return load_gcm2 <= max_load_gcm2() * (1 + kLoadLimitRelativeTolerance); }

double flange_axis_inertia_kgm2(const mjModel* model, mjData* data) {
  mj_forward(model, data);
  const int joint = mj_name2id(model, mjOBJ_JOINT, "rotor");
  if (joint < 0) {
    throw std::invalid_argument("MuJoCo model has no joint named \"rotor\"");
  }
  const int dof = model->jnt_dofadr[joint];
  return data->qM[model->dof_Madr[dof]];
}

namespace {
// The model card's drive train onto the compiled module (A-TWIN-4,
// A-TWIN-20, A-TWIN-22): the rotor's armature, bearing friction and drag;
// the compliance's stiffness and damping; the flange's own inertia is the
// rest of J_intern (manual 3.5.4). Then MuJoCo's derived constants again.
void apply_mechanics(mjModel* m, const MechanicsConstants& c, const std::string& origin) {
  const int rotor = mj_name2id(m, mjOBJ_JOINT, "rotor");
  const int flange = mj_name2id(m, mjOBJ_JOINT, "flange");
  const int flange_body = mj_name2id(m, mjOBJ_BODY, "flange");
  if (rotor < 0 || flange < 0 || flange_body < 0) {
    throw std::invalid_argument(origin + ": the module model needs joints \"rotor\", \"flange\" and body \"flange\"");
  }
  const double flange_own = kInternalInertia_kgm2 - c.rotor_inertia_kgm2;
  if (!(flange_own > 0)) {
    throw std::invalid_argument("model card: rotor_inertia " + num(c.rotor_inertia_kgm2) +
                                " kg m^2 must be below J_intern = 0.115e-3 kg m^2 (manual 3.5.4)");
  }
  const int rotor_dof = m->jnt_dofadr[rotor];
  const int flange_dof = m->jnt_dofadr[flange];
  m->dof_armature[rotor_dof] = c.rotor_inertia_kgm2;
  // The model as a viewer should show it; a stepping Plant moves the two
  // dampings into a form its constraint solver sees (A-TWIN-48).
  m->dof_damping[rotor_dof] = c.viscous_friction_Nms_per_rad;
  m->dof_frictionloss[rotor_dof] = c.coulomb_friction_Nm;
  m->jnt_stiffness[flange] = c.torsional_stiffness_Nm_per_rad;
  m->dof_damping[flange_dof] = c.torsional_damping_Nms_per_rad;
  const double* ipos = m->body_ipos + 3 * flange_body;
  m->body_inertia[3 * flange_body + 2] =
      flange_own - m->body_mass[flange_body] * (ipos[0] * ipos[0] + ipos[1] * ipos[1]);
  MjDataPtr data(mj_makeData(m));
  mj_setConst(m, data.get());
}
} // namespace

namespace {
// The module's builtin textures (sky, floor) at 8 x 8 pixels: generating
// them is ~87 % of a compile (22 ms vs 3 ms measured, issue 28), and a
// model that is never rendered does not need them.
std::string without_texture_detail(std::string xml) {
  static const std::regex texture(R"re(<texture\b[^>]*>)re");
  static const std::regex size(R"re(\b(width|height)\s*=\s*"[0-9]+")re");
  std::string out;
  std::size_t last = 0;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), texture); it != std::sregex_iterator(); ++it) {
    out += xml.substr(last, static_cast<std::size_t>(it->position(0)) - last);
    out += std::regex_replace(it->str(), size, "$1=\"8\"");
    last = static_cast<std::size_t>(it->position(0) + it->length(0));
  }
  return out + xml.substr(last);
}

// How much of the module a model keeps for drawing: full textures
// (renderers), coarse textures (checks, figures), or neither textures nor
// drawing geoms (twins never drawn, without contacts: twin/model_lean.hpp).
enum class Detail { Full, Coarse, Lean };

Detail detail_for(bool visual_detail, const std::vector<HardStop>& hard_stops) {
  if (visual_detail) return Detail::Full;
  return hard_stops.empty() ? Detail::Lean : Detail::Coarse; // with hard stops the geoms touch
}

BuiltModel build(const LoadSpec& load, const std::vector<HardStop>& hard_stops, double physics_dt_s,
                 const MechanicsConstants& mechanics, const std::string& module_model_path, Detail detail);

// What a built model depends on (twin/model_cache.hpp).
ModelKey model_key(const ComposedModel& composed, double physics_dt_s, const MechanicsConstants& mechanics,
                   Detail detail) {
  return ModelKey{composed.xml, composed.files, static_cast<int>(detail), physics_dt_s, mechanics};
}

// Compiled from `xml` (the key's text, as drawn or coarse), with the card's
// drive train and the physics step (contacts only with hard stops).
MjModelPtr compiled(const std::string& xml, const ModelKey& key, bool contacts, const std::string& origin) {
  MjModelPtr model = compile_mjcf(xml, origin, key.files);
  mjModel* m = model.get();
  m->opt.timestep = key.physics_dt_s;
  apply_mechanics(m, key.mechanics, origin);
  if (!contacts) {
    m->opt.disableflags |= mjDSBL_CONTACT; // nothing can touch: skip collision detection
  }
  return model;
}

// A-TWIN-42: the lean model only where it steps exactly as the coarse one
// (same_dynamics); else, or if its text does not compile, the coarse one.
MjModelPtr leanest(const std::string& coarse_xml, MjModelPtr coarse, const ModelKey& key, const std::string& origin) {
  try {
    MjModelPtr lean = compiled(lean_xml(coarse_xml, coarse.get()), key, false, origin);
    if (same_dynamics(lean.get(), coarse.get())) return lean;
  } catch (const std::exception&) {
    // a load's text the lean edit breaks: the coarse model then
  }
  return coarse;
}
} // namespace

double built_load_inertia_kgm2(const LoadSpec& load, const std::vector<HardStop>& hard_stops, double physics_dt_s,
                               const MechanicsConstants& mechanics, const std::string& module_model_path) {
  // The model a sizing twin runs (same key, one compile for both).
  const Detail detail = detail_for(false, hard_stops);
  const ComposedModel composed = compose_model(load, hard_stops, module_model_path);
  if (const auto kept = cached_figures(model_key(composed, physics_dt_s, mechanics, detail))) {
    return kept->load_inertia_kgm2;
  }
  // The lean model steps bit for bit as the coarse one (same_dynamics: the
  // same moving bodies, inertials and armature), so its figures are the
  // coarse one's: a load checked before needs no compile here (issue 37).
  if (detail == Detail::Lean) {
    if (const auto kept = cached_figures(model_key(composed, physics_dt_s, mechanics, Detail::Coarse))) {
      return kept->load_inertia_kgm2;
    }
  }
  return build(load, hard_stops, physics_dt_s, mechanics, module_model_path, detail).load_inertia_kgm2;
}

BuiltModel build_model(const LoadSpec& load, const std::vector<HardStop>& hard_stops, double physics_dt_s,
                       const MechanicsConstants& mechanics, const std::string& module_model_path, bool visual_detail) {
  return build(load, hard_stops, physics_dt_s, mechanics, module_model_path, detail_for(visual_detail, hard_stops));
}

BuiltModel check_load(const LoadSpec& load) {
  return build(load, {}, 1e-4, default_module_model().mechanics, default_module_model_path(), Detail::Coarse);
}

namespace {
BuiltModel build(const LoadSpec& load, const std::vector<HardStop>& hard_stops, double physics_dt_s,
                 const MechanicsConstants& mechanics, const std::string& module_model_path, Detail detail) {
  if (!(physics_dt_s > 0.0) || !std::isfinite(physics_dt_s)) {
    throw std::invalid_argument("physics_dt_s must be positive, got " + num(physics_dt_s));
  }
  const std::string origin = describe_load(load);
  const ComposedModel composed = compose_model(load, hard_stops, module_model_path);
  ModelKey key = model_key(composed, physics_dt_s, mechanics, detail);
  if (std::optional<BuiltModel> kept = cached_model(key)) return std::move(*kept); // issue 31: compiled once
  BuiltModel built;
  const std::string xml = detail == Detail::Full ? key.xml : without_texture_detail(key.xml);
  // The lean model is made from the coarse one (same text, same compile):
  // a load checked before (check_load, as every load file's parser and the
  // studio's load panel do) has it compiled already.
  std::optional<BuiltModel> coarse;
  if (detail == Detail::Lean) coarse = cached_model(model_key(composed, physics_dt_s, mechanics, Detail::Coarse));
  built.model = coarse ? std::move(coarse->model) : compiled(xml, key, !hard_stops.empty(), origin);
  if (detail == Detail::Lean) built.model = leanest(xml, std::move(built.model), key, origin);
  mjModel* m = built.model.get();
  // The module's own joints: "rotor" and "flange" (the compliance).
  if (m->njnt != 2) {
    throw std::invalid_argument(origin + ": a load must be rigid, but it adds " + std::to_string(m->njnt - 2) +
                                " joint(s) of its own");
  }
  MjDataPtr data(mj_makeData(m));
  const int rotor = mj_name2id(m, mjOBJ_JOINT, "rotor");
  built.axis_inertia_kgm2 = flange_axis_inertia_kgm2(m, data.get());
  // The rotor's armature and the rotor's and flange's own inertials are
  // J_intern (A-TWIN-4), not load.
  auto own_about_axis = [m](int body) {
    const double* ipos = m->body_ipos + 3 * body;
    return m->body_inertia[3 * body + 2] + m->body_mass[body] * (ipos[0] * ipos[0] + ipos[1] * ipos[1]);
  };
  const int rotor_body = m->jnt_bodyid[rotor];
  const int flange_body = mj_name2id(m, mjOBJ_BODY, "flange");
  built.load_inertia_kgm2 = built.axis_inertia_kgm2 - m->dof_armature[m->jnt_dofadr[rotor]] -
                            own_about_axis(rotor_body) - (flange_body >= 0 ? own_about_axis(flange_body) : 0.0);
  const double load_gcm2 = kgm2_to_gcm2(built.load_inertia_kgm2);
  if (!within_load_limit(load_gcm2)) {
    throw std::invalid_argument(origin + ": load inertia about the axis is " + round_gcm2(load_gcm2) +
                                " g cm^2, above the module's limit of 15000 g cm^2 (manual 3.5.6, 6.2 index 64.4)");
  }
  remember_model(std::move(key), built);
  return built;
}
} // namespace

} // namespace sreh
