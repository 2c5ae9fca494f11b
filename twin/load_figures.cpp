#include "twin/load_figures.hpp"

#include <cmath>

#include "device_logic/units.hpp"
#include "twin/load_builder.hpp"
#include "twin/load_parts.hpp"

namespace sreh {
namespace {

bool inside(const mjModel* m, int body, int root) {
  for (int b = body; b > 0; b = m->body_parentid[b]) {
    if (b == root) return true;
  }
  return false;
}

// Body b's mass, first moment and inertia about the world z axis through
// the flange's centre (the module stands upright at angle 0).
void add_body(const mjModel* m, const mjData* d, int b, const double axis_xy[2], PartFigures& into, double moment[3]) {
  const double mass = m->body_mass[b];
  const double* R = d->ximat + 9 * b; // principal frame -> world
  const double* I = m->body_inertia + 3 * b;
  // z z element of R diag(I) R^T.
  const double izz = R[6] * R[6] * I[0] + R[7] * R[7] * I[1] + R[8] * R[8] * I[2];
  const double dx = d->xipos[3 * b] - axis_xy[0], dy = d->xipos[3 * b + 1] - axis_xy[1];
  into.mass_kg += mass;
  into.inertia_kgm2 += izz + mass * (dx * dx + dy * dy);
  for (int k = 0; k < 3; ++k) moment[k] += mass * d->xipos[3 * b + k];
}

} // namespace

LoadFigures load_figures(const LoadSpec& load) {
  BuiltModel built = check_load(load);
  const mjModel* m = built.model.get();
  MjDataPtr data(mj_makeData(m));
  mj_forward(m, data.get());
  const mjData* d = data.get();
  LoadFigures f;
  f.inertia_kgm2 = built.load_inertia_kgm2;
  const int flange = mj_name2id(m, mjOBJ_BODY, "flange");
  const double* face = d->xpos + 3 * flange; // the mounting face's centre, on the axis
  const double axis_xy[2] = {face[0], face[1]};
  std::vector<int> roots; // one per part
  const auto* assembly = std::get_if<AssemblyLoad>(&load);
  if (assembly != nullptr) {
    for (std::size_t k = 0; k < assembly->parts.size(); ++k) {
      roots.push_back(mj_name2id(m, mjOBJ_BODY, part_body_name(k).c_str()));
    }
  }
  double total_moment[3] = {0, 0, 0};
  PartFigures total;
  for (std::size_t k = 0; k < (assembly ? roots.size() : 1); ++k) {
    PartFigures part;
    part.shape = assembly ? part_kind(assembly->parts[k].shape) : "load";
    part.name = assembly ? assembly->parts[k].name : "";
    double moment[3] = {0, 0, 0};
    for (int b = 1; b < m->nbody; ++b) {
      // A one-shape load: every body below the flange (an MJCF file's body has its own name).
      const bool mine = assembly ? inside(m, b, roots[k]) : (inside(m, b, flange) && b != flange);
      if (mine) add_body(m, d, b, axis_xy, part, moment);
    }
    for (int c = 0; c < 3; ++c) {
      part.com_m[static_cast<std::size_t>(c)] = part.mass_kg > 0 ? moment[c] / part.mass_kg - face[c] : 0.0;
      total_moment[c] += moment[c];
    }
    total.mass_kg += part.mass_kg;
    f.parts.push_back(part);
  }
  f.mass_kg = total.mass_kg;
  for (int c = 0; c < 3; ++c) f.com_m[static_cast<std::size_t>(c)] = f.mass_kg > 0 ? total_moment[c] / f.mass_kg - face[c] : 0.0;
  for (int c = 0; c < 3; ++c) f.face_world_m[static_cast<std::size_t>(c)] = face[c];
  f.com_radius_m = std::hypot(f.com_m[0], f.com_m[1]);
  f.gravity_m_s2 = std::sqrt(m->opt.gravity[0] * m->opt.gravity[0] + m->opt.gravity[1] * m->opt.gravity[1] +
                             m->opt.gravity[2] * m->opt.gravity[2]); // the module model's, as the twin tilts it
  return f;
}

double gravity_torque_max_Nm(const LoadFigures& f, double tilt_deg) {
  return f.mass_kg * f.gravity_m_s2 * f.com_radius_m * std::abs(std::sin(deg_to_rad(tilt_deg)));
}

} // namespace sreh
