#include "twin/load_parts.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

#include "device_logic/units.hpp"

namespace sreh {
namespace {

constexpr double kPointSteelDensity_kg_m3 = 7850.0; // a point mass is drawn as a steel sphere (A-TWIN-6)
constexpr double kPointInertia_kgm2 = 1e-12;   // MuJoCo needs an inertia above 0
constexpr int kPartRingSegments = 32;              // ring drawn from box segments (visual only)

std::string part_num(double v) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

void positive(double v, const std::string& what, const std::string& origin) {
  if (!(v > 0.0) || !std::isfinite(v)) throw std::invalid_argument(origin + ": " + what + " must be positive and finite, got " + part_num(v));
}

// Roll, pitch, yaw about the fixed x, y, z axes in that order: q = qz qy qx.
std::string quat_of(const std::array<double, 3>& rpy_deg) {
  const double r = deg_to_rad(rpy_deg[0]) / 2, p = deg_to_rad(rpy_deg[1]) / 2, y = deg_to_rad(rpy_deg[2]) / 2;
  const double cr = std::cos(r), sr = std::sin(r), cp = std::cos(p), sp = std::sin(p), cy = std::cos(y), sy = std::sin(y);
  return part_num(cy * cp * cr + sy * sp * sr) + " " + part_num(cy * cp * sr - sy * sp * cr) + " " + part_num(cy * sp * cr + sy * cp * sr) +
         " " + part_num(sy * cp * cr - cy * sp * sr);
}

struct PartXml {
  const std::string& name;   // the part body's name, prefix of its geoms
  const std::string& origin; // for messages
  const std::string& module_assets;
  LoadXml& out;

  void operator()(const DiskLoad& l) const {
    positive(l.mass_kg, "disk mass_kg", origin);
    positive(l.radius_m, "disk radius_m", origin);
    positive(l.thickness_m, "disk thickness_m", origin);
    out.body += "<geom name=\"" + name + "_disk\" type=\"cylinder\" size=\"" + part_num(l.radius_m) + " " + part_num(l.thickness_m / 2) +
                "\" mass=\"" + part_num(l.mass_kg) + "\" material=\"load_alu\"/>";
  }
  void operator()(const RingLoad& l) const {
    positive(l.mass_kg, "ring mass_kg", origin);
    positive(l.outer_radius_m, "ring outer_radius_m", origin);
    positive(l.thickness_m, "ring thickness_m", origin);
    if (!(l.inner_radius_m >= 0 && l.inner_radius_m < l.outer_radius_m)) {
      throw std::invalid_argument(origin + ": ring inner_radius_m must be 0 .. below outer_radius_m");
    }
    const double ri2 = l.inner_radius_m * l.inner_radius_m, ro2 = l.outer_radius_m * l.outer_radius_m, t = l.thickness_m;
    const double izz = l.mass_kg * (ri2 + ro2) / 2, ixx = l.mass_kg * (3 * (ri2 + ro2) + t * t) / 12;
    // MuJoCo has no hollow primitive: exact inertial, massless box segments to show it.
    out.body += "<inertial pos=\"0 0 0\" mass=\"" + part_num(l.mass_kg) + "\" diaginertia=\"" + part_num(ixx) + " " + part_num(ixx) + " " +
                part_num(izz) + "\"/>";
    const double r_mid = (l.inner_radius_m + l.outer_radius_m) / 2, half_radial = (l.outer_radius_m - l.inner_radius_m) / 2;
    const double half_tangential = kPi * r_mid / kPartRingSegments * 1.02;
    for (int k = 0; k < kPartRingSegments; ++k) {
      const double a = 2 * kPi * k / kPartRingSegments;
      out.body += "<geom name=\"" + name + "_ring_" + std::to_string(k) + "\" type=\"box\" size=\"" + part_num(half_radial) + " " +
                  part_num(half_tangential) + " " + part_num(t / 2) + "\" pos=\"" + part_num(r_mid * std::cos(a)) + " " +
                  part_num(r_mid * std::sin(a)) + " 0\" euler=\"0 0 " + part_num(a) + "\" mass=\"0\" material=\"load_alu\"/>";
    }
  }
  void operator()(const BoxLoad& l) const {
    positive(l.mass_kg, "box mass_kg", origin);
    positive(l.x_m, "box x_m", origin);
    positive(l.y_m, "box y_m", origin);
    positive(l.z_m, "box z_m", origin);
    out.body += "<geom name=\"" + name + "_box\" type=\"box\" size=\"" + part_num(l.x_m / 2) + " " + part_num(l.y_m / 2) + " " +
                part_num(l.z_m / 2) + "\" mass=\"" + part_num(l.mass_kg) + "\" material=\"load_alu\"/>";
  }
  void operator()(const CylinderPart& l) const {
    positive(l.mass_kg, "cylinder mass_kg", origin);
    positive(l.radius_m, "cylinder radius_m", origin);
    positive(l.length_m, "cylinder length_m", origin);
    out.body += "<geom name=\"" + name + "_cylinder\" type=\"cylinder\" size=\"" + part_num(l.radius_m) + " " +
                part_num(l.length_m / 2) + "\" mass=\"" + part_num(l.mass_kg) + "\" material=\"load_alu\"/>";
  }
  void operator()(const SpherePart& l) const {
    positive(l.mass_kg, "sphere mass_kg", origin);
    positive(l.radius_m, "sphere radius_m", origin);
    out.body += "<geom name=\"" + name + "_sphere\" type=\"sphere\" size=\"" + part_num(l.radius_m) + "\" mass=\"" +
                part_num(l.mass_kg) + "\" material=\"load_steel\"/>";
  }
  void operator()(const PointPart& l) const {
    positive(l.mass_kg, "point mass_kg", origin);
    const double r = std::cbrt(3 * l.mass_kg / (4 * kPi * kPointSteelDensity_kg_m3));
    out.body += "<inertial pos=\"0 0 0\" mass=\"" + part_num(l.mass_kg) + "\" diaginertia=\"" + part_num(kPointInertia_kgm2) + " " +
                part_num(kPointInertia_kgm2) + " " + part_num(kPointInertia_kgm2) + "\"/><geom name=\"" + name +
                "_point\" type=\"sphere\" size=\"" + part_num(r) + "\" mass=\"0\" material=\"load_steel\"/>";
  }
  void operator()(const MeshPart& l) const {
    positive(l.scale, "mesh scale", origin);
    if ((l.mass_kg > 0) == (l.density_kg_m3 > 0)) {
      throw std::invalid_argument(origin + ": mesh: give mass_kg or density_kg_m3 (one of them, above 0)");
    }
    VfsFile file;
    try {
      file = mesh_vfs_file(l.path, "sreh_" + name + ".stl");
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(origin + ": mesh: " + e.what());
    }
    out.files.push_back(std::move(file));
    const std::string s = part_num(l.scale);
    out.assets += "<mesh name=\"" + name + "_mesh\" file=\"" + out.files.back().name + "\" scale=\"" + s + " " + s + " " + s + "\"/>";
    // MuJoCo computes volume, centre of mass and inertia of the solid mesh.
    out.body += "<geom name=\"" + name + "_mesh\" type=\"mesh\" mesh=\"" + name + "_mesh\" " +
                (l.mass_kg > 0 ? "mass=\"" + part_num(l.mass_kg) + "\"" : "density=\"" + part_num(l.density_kg_m3) + "\"") +
                " material=\"load_alu\"/>";
  }
  void operator()(const MjcfLoad& l) const {
    LoadXml user;
    try {
      user = mjcf_load_xml(l.path, module_assets, name + "/");
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(origin + ": mjcf: " + e.what());
    }
    out.body += user.body;
    out.assets += user.assets;
    for (VfsFile& f : user.files) out.files.push_back(std::move(f));
  }
};

} // namespace

std::string part_body_name(std::size_t k) { return "load_p" + std::to_string(k); }

std::string part_kind(const PartShape& shape) {
  static const char* const kKinds[] = {"disk", "ring", "box", "cylinder", "sphere", "point", "mesh", "mjcf"};
  return kKinds[shape.index()];
}

LoadXml assembly_xml(const AssemblyLoad& load, const std::string& module_assets) {
  if (load.parts.empty()) throw std::invalid_argument(load.origin + ": load.parts: give at least one part");
  LoadXml out;
  out.body = "<body name=\"load\">";
  for (std::size_t k = 0; k < load.parts.size(); ++k) {
    const LoadPart& p = load.parts[k];
    const std::string name = part_body_name(k);
    const std::string origin = p.origin.empty() ? "load part " + std::to_string(k) : p.origin;
    for (double v : p.at_m) {
      if (!std::isfinite(v)) throw std::invalid_argument(origin + ": at_m must be finite");
    }
    for (double v : p.rpy_deg) {
      if (!std::isfinite(v)) throw std::invalid_argument(origin + ": rpy_deg must be finite");
    }
    out.body += "<body name=\"" + name + "\" pos=\"" + part_num(p.at_m[0]) + " " + part_num(p.at_m[1]) + " " + part_num(p.at_m[2]) +
                "\" quat=\"" + quat_of(p.rpy_deg) + "\">";
    std::visit(PartXml{name, origin, module_assets, out}, p.shape);
    out.body += "</body>";
  }
  out.body += "</body>";
  return out;
}

} // namespace sreh
