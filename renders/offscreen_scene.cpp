#include "renders/offscreen_scene.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace sreh {

// The degree scale on the housing top (issue 29, A-RENDERS-15): ticks
// every 10 deg (30 and 90 deg longer) on the ring between the collar and
// the housing's edge, numbers at 0/90/180/270 just outside it. Fixed to
// the housing: the flange's zero direction (all hinges at 0) turned about
// the flange axis by the factory angle (qpos sense, A-RENDERS-7).
void add_degree_scale(const mjModel* m, const mjData* d, mjvScene& scn, const SceneIds& ids, std::optional<double> ghost_rad,
                      bool pointer_labels) {
  if (ids.flange_jnt < 0 || ids.housing_geom < 0 || m->geom_type[ids.housing_geom] != mjGEOM_CYLINDER) return;
  const double* u = d->xaxis + 3 * ids.flange_jnt;
  const double sign = u[2] >= 0 ? 1.0 : -1.0;
  const double up[3] = {sign * u[0], sign * u[1], sign * u[2]};
  // Zero direction: the outermost hinge body's x axis in its parent's frame.
  int outer = m->jnt_bodyid[ids.flange_jnt];
  while (m->body_parentid[outer] > 0 && m->body_jntnum[m->body_parentid[outer]] > 0) outer = m->body_parentid[outer];
  double parent_quat[4], zero_quat[4], zero_dir[3];
  mju_mat2Quat(parent_quat, d->xmat + 9 * m->body_parentid[outer]);
  mju_mulQuat(zero_quat, parent_quat, m->body_quat + 4 * outer);
  const double x_axis[3] = {1, 0, 0};
  mju_rotVecQuat(zero_dir, x_axis, zero_quat);
  const double* hc = d->geom_xpos + 3 * ids.housing_geom;
  const double r_out = m->geom_size[3 * ids.housing_geom];
  const double top = m->geom_size[3 * ids.housing_geom + 1];
  const double r_in = ids.collar_geom >= 0 ? m->geom_size[3 * ids.collar_geom] : 0.8 * r_out;
  const double ring = 0.95 * (r_out - r_in);
  const double flange_rad = flange_angle_rad(m, d);
  const float tick_rgba[4] = {0.12f, 0.12f, 0.13f, 1.0f}, clear[4] = {0, 0, 0, 0};
  for (int deg = 0; deg < 360 && scn.ngeom + 2 <= scn.maxgeom; deg += 10) {
    double q[4], dir[3], side[3];
    mju_axisAngle2Quat(q, u, deg * std::numbers::pi / 180.0);
    mju_rotVecQuat(dir, zero_dir, q);
    mju_cross(side, up, dir);
    const double len = ring * (deg % 90 == 0 ? 1.0 : deg % 30 == 0 ? 0.6 : 0.35);
    const double r = r_out - 0.02 * (r_out - r_in) - 0.5 * len;
    const mjtNum size[3] = {0.5 * len, 0.00022 * (deg % 30 == 0 ? 1.5 : 1.0), 0.00012};
    mjtNum pos[3], mat[9];
    for (int k = 0; k < 3; ++k) {
      pos[k] = hc[k] + (top + 0.0001) * up[k] + r * dir[k];
      mat[3 * k] = dir[k], mat[3 * k + 1] = side[k], mat[3 * k + 2] = up[k];
    }
    mjvGeom& tick = scn.geoms[scn.ngeom++];
    mjv_initGeom(&tick, mjGEOM_BOX, size, pos, mat, tick_rgba);
    tick.category = mjCAT_DECOR;
    if (deg % 90 != 0) continue;
    // The number: an invisible marker carrying the label just outside the
    // housing. MuJoCo draws labels over everything: a number the module
    // or its load hides from the camera is left out.
    const mjtNum dot[3] = {0.0005, 0.0005, 0.0005};
    for (int k = 0; k < 3; ++k) pos[k] = hc[k] + (top + 0.0015) * up[k] + (r_out + 0.004) * dir[k];
    if (!seen_by_camera(m, d, scn, ids.ghost_body, pos)) continue;
    // Nor where a pointer's label would be written over it.
    auto near = [&](double rad) {
      return std::abs(std::remainder(rad - deg * std::numbers::pi / 180.0, 2 * std::numbers::pi)) < 0.35;
    };
    if (pointer_labels && (near(flange_rad) || (ghost_rad && near(*ghost_rad)))) continue;
    mjvGeom& number = scn.geoms[scn.ngeom++];
    mjv_initGeom(&number, mjGEOM_SPHERE, dot, pos, nullptr, clear);
    number.category = mjCAT_DECOR;
    std::snprintf(number.label, sizeof number.label, "%d", deg);
  }
}

// True when nothing of the model lies between the camera and `p`.
bool seen_by_camera(const mjModel* m, const mjData* d, const mjvScene& scn, int ghost_body, const mjtNum p[3]) {
  mjtNum eye[3], ray[3];
  for (int k = 0; k < 3; ++k) {
    eye[k] = 0.5 * (scn.camera[0].pos[k] + scn.camera[1].pos[k]);
    ray[k] = p[k] - eye[k];
  }
  const mjtNum dist = mju_normalize3(ray);
  int hit = -1;
  const mjtNum at = mj_ray(m, d, eye, ray, nullptr, 1, ghost_body, &hit);
  return at < 0 || at > dist - 1e-4;
}

// Near and far clipping planes in metres: MuJoCo scales them by the
// model's extent, which the floor's 20 m strips make 25 m (mj_setConst
// recomputes it for the twin's model whatever the MJCF says), so the near
// plane would cut into the module. The frustum is rescaled in the scene.
void set_clip_planes(mjvScene& scn) {
  constexpr float kNear_m = 0.002f, kFar_m = 80.0f;
  for (mjvGLCamera& c : scn.camera) {
    if (!(c.frustum_near > 0)) continue;
    const float k = kNear_m / c.frustum_near;
    c.frustum_near = kNear_m;
    c.frustum_far = kFar_m;
    c.frustum_top *= k;
    c.frustum_bottom *= k;
    c.frustum_center *= k;
  }
}

// The skybox only where the camera can see past the floor (issue 31):
// filling the whole MSAA frame with it cost 19 of 67 ms of CPU per 720p
// frame, and the floor around the table (models/sreh50.xml) fills the
// default and top views. Decided once, from the camera of the first
// frame: true when the rays through the image's corners and the middles
// of its top and bottom edges hit a plane (the table or a floor strip).
bool planes_fill_view(const mjModel* m, const mjData* d, const mjvScene& scn, double aspect) {
  const mjvGLCamera c = mjv_averageCamera(&scn.camera[0], &scn.camera[1]); // the mono camera
  double right[3];
  const double fwd[3] = {c.forward[0], c.forward[1], c.forward[2]}, up[3] = {c.up[0], c.up[1], c.up[2]};
  mju_cross(right, fwd, up);
  const double half_w = 0.5 * (c.frustum_top - c.frustum_bottom) * aspect;
  // A ray from the camera hits one of the model's planes within its size.
  auto hits_a_plane = [&](const double dir[3]) {
    for (int g = 0; g < m->ngeom; ++g) {
      if (m->geom_type[g] != mjGEOM_PLANE) continue;
      const double* p0 = d->geom_xpos + 3 * g;
      const double* x = d->geom_xmat + 9 * g;
      const double normal[3] = {x[2], x[5], x[8]}, ax[3] = {x[0], x[3], x[6]}, ay[3] = {x[1], x[4], x[7]};
      const double denom = mju_dot3(dir, normal);
      if (std::abs(denom) < 1e-12) continue;
      const double rel[3] = {p0[0] - c.pos[0], p0[1] - c.pos[1], p0[2] - c.pos[2]};
      const double t = mju_dot3(rel, normal) / denom;
      if (t <= 0) continue;
      const double hit[3] = {c.pos[0] + t * dir[0] - p0[0], c.pos[1] + t * dir[1] - p0[1], c.pos[2] + t * dir[2] - p0[2]};
      if (std::abs(mju_dot3(hit, ax)) <= m->geom_size[3 * g] && std::abs(mju_dot3(hit, ay)) <= m->geom_size[3 * g + 1]) {
        return true;
      }
    }
    return false;
  };
  // The planes are flat and the view a rectangle: its corners and edge
  // midpoints on planes leave no gap for the sky between adjacent strips.
  for (double sx : {-1.0, 0.0, 1.0}) {
    for (double v : {static_cast<double>(c.frustum_bottom), static_cast<double>(c.frustum_top)}) {
      double dir[3];
      for (int k = 0; k < 3; ++k) dir[k] = c.frustum_near * fwd[k] + v * up[k] + (c.frustum_center + sx * half_w) * right[k];
      if (!hits_a_plane(dir)) return false;
    }
  }
  return true;
}

} // namespace sreh
