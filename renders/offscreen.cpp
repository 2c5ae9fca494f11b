// OSMesa + MuJoCo off-screen renderer (design/mujoco.md "Rendering off-screen").
#include "renders/offscreen.hpp"

#include <GL/osmesa.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "renders/offscreen_scene.hpp"
#include "renders/offscreen_text.hpp"

namespace sreh {

LedLook led_look(LedColor c) {
  // A-RENDERS-2: sRGB-ish colours of a lit LED band; off is a dark grey
  // diffuser without emission so it never reads as a colour.
  switch (c) {
    case LedColor::Off: return {{0.18f, 0.18f, 0.19f, 1.0f}, 0.0f};
    case LedColor::Green: return {{0.05f, 0.90f, 0.15f, 1.0f}, 0.6f};
    case LedColor::Yellow: return {{0.95f, 0.85f, 0.05f, 1.0f}, 0.6f};
    case LedColor::Blue: return {{0.10f, 0.25f, 1.00f, 1.0f}, 0.6f};
    case LedColor::Red: return {{1.00f, 0.05f, 0.05f, 1.0f}, 0.6f};
    case LedColor::Orange: return {{1.00f, 0.45f, 0.02f, 1.0f}, 0.6f};
    case LedColor::White: return {{0.95f, 0.95f, 0.95f, 1.0f}, 0.6f};
    case LedColor::Violet: return {{0.60f, 0.10f, 0.95f, 1.0f}, 0.6f};
  }
  return {{0.18f, 0.18f, 0.19f, 1.0f}, 0.0f};
}

double flange_angle_rad(const mjModel* m, const mjData* d) {
  // Two-mass plant (issue 14): the flange hangs on the rotor, so its angle
  // is the sum of the co-axial hinges from the flange body up to the world.
  const int jnt = mj_name2id(m, mjOBJ_JOINT, "flange");
  if (jnt < 0) return 0.0;
  double angle = 0;
  for (int b = m->jnt_bodyid[jnt]; b > 0; b = m->body_parentid[b]) {
    for (int j = m->body_jntadr[b]; j >= 0 && j < m->body_jntadr[b] + m->body_jntnum[b]; ++j) {
      if (m->jnt_type[j] == mjJNT_HINGE) angle += d->qpos[m->jnt_qposadr[j]];
    }
  }
  return angle;
}

void flip_rows(uint8_t* rgb, int width, int height) {
  const std::size_t row = static_cast<std::size_t>(width) * 3;
  std::vector<uint8_t> tmp(row);
  for (int y = 0; y < height / 2; ++y) {
    uint8_t* a = rgb + static_cast<std::size_t>(y) * row;
    uint8_t* b = rgb + static_cast<std::size_t>(height - 1 - y) * row;
    std::memcpy(tmp.data(), a, row);
    std::memcpy(a, b, row);
    std::memcpy(b, tmp.data(), row);
  }
}

namespace {

// Height along `up` of the top of everything that turns with the flange.
double axial_half_extent(const mjModel* m, const mjData* d, int g, const double* up) {
  const double* x = d->geom_xmat + 9 * g;
  const double* size = m->geom_size + 3 * g;
  const double c[3][3] = {{x[0], x[3], x[6]}, {x[1], x[4], x[7]}, {x[2], x[5], x[8]}}; // geom axes in world
  const double along_z = std::abs(mju_dot3(up, c[2]));
  switch (m->geom_type[g]) {
    case mjGEOM_BOX: return std::abs(mju_dot3(up, c[0])) * size[0] + std::abs(mju_dot3(up, c[1])) * size[1] + along_z * size[2];
    case mjGEOM_CYLINDER: return along_z * size[1] + std::sqrt(std::max(0.0, 1 - along_z * along_z)) * size[0];
    case mjGEOM_CAPSULE: return along_z * size[1] + size[0];
    case mjGEOM_SPHERE: return size[0];
    default: return m->geom_rbound[g];
  }
}

double rotating_top(const mjModel* m, const mjData* d, int flange_jnt, const double* up) {
  const double* a = d->xanchor + 3 * flange_jnt;
  const int root = m->body_rootid[m->jnt_bodyid[flange_jnt]];
  double top = -std::numeric_limits<double>::max();
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->body_rootid[m->geom_bodyid[g]] != root || m->geom_group[g] > 2) continue;
    const double* p = d->geom_xpos + 3 * g;
    const double rel[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    top = std::max(top, mju_dot3(rel, up) + axial_half_extent(m, d, g, up));
  }
  return top;
}

// Points on the hull the camera must show: a cylinder about the flange axis
// around every visible non-plane geom, raised to the lifted pointers
// (A-RENDERS-1). Invariant under flange rotation, so the camera does not
// breathe with an off-centre load.
std::vector<std::array<double, 3>> hull_points(const mjModel* m, const mjData* d, int flange_jnt, int ghost_body) {
  std::vector<std::array<double, 3>> pts;
  if (flange_jnt < 0) {
    const double* c = m->stat.center;
    const double e = m->stat.extent;
    for (int i = 0; i < 8; ++i) pts.push_back({c[0] + (i & 1 ? e : -e), c[1] + (i & 2 ? e : -e), c[2] + (i & 4 ? e : -e)});
    return pts;
  }
  const double* a = d->xanchor + 3 * flange_jnt;
  const double* u0 = d->xaxis + 3 * flange_jnt;
  const double sign = u0[2] >= 0 ? 1.0 : -1.0;
  const double u[3] = {sign * u0[0], sign * u0[1], sign * u0[2]};
  double r_max = 0, h_min = std::numeric_limits<double>::max(), h_max = -h_min;
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_type[g] == mjGEOM_PLANE || m->geom_group[g] > 2) continue;
    if (ghost_body >= 0 && m->geom_bodyid[g] == ghost_body) continue; // placed on top below
    const double* p = d->geom_xpos + 3 * g;
    const double rel[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    const double h = mju_dot3(rel, u);
    const double radial[3] = {rel[0] - h * u[0], rel[1] - h * u[1], rel[2] - h * u[2]};
    const double rb = std::min(m->geom_rbound[g], 0.5); // huge geoms (walls) would frame nothing
    r_max = std::max(r_max, mju_norm3(radial) + rb);
    h_min = std::min(h_min, h - axial_half_extent(m, d, g, u));
    h_max = std::max(h_max, h + axial_half_extent(m, d, g, u));
  }
  if (ghost_body >= 0) {
    const double top = rotating_top(m, d, flange_jnt, u);
    for (int g = 0; g < m->ngeom; ++g) {
      if (m->geom_bodyid[g] != ghost_body) continue;
      const double* gp = m->geom_pos + 3 * g;
      r_max = std::max(r_max, std::hypot(gp[0], gp[1]) + m->geom_rbound[g]);
      h_max = std::max(h_max, top + 0.0015 + gp[2] + m->geom_rbound[g]);
    }
  }
  if (h_min > h_max) return hull_points(m, d, -1, -1);
  double n[3] = {1, 0, 0};
  if (std::abs(u[0]) > 0.9) n[0] = 0, n[1] = 1;
  const double along = mju_dot3(n, u);
  double p1[3] = {n[0] - along * u[0], n[1] - along * u[1], n[2] - along * u[2]};
  mju_normalize3(p1);
  double p2[3];
  mju_cross(p2, u, p1);
  constexpr int kAround = 24;
  for (double h : {h_min, h_max}) {
    for (int k = 0; k < kAround; ++k) {
      const double ang = 2 * std::numbers::pi * k / kAround;
      const double c = std::cos(ang) * r_max, sn = std::sin(ang) * r_max;
      pts.push_back({a[0] + h * u[0] + c * p1[0] + sn * p2[0], a[1] + h * u[1] + c * p1[1] + sn * p2[1],
                     a[2] + h * u[2] + c * p1[2] + sn * p2[2]});
    }
  }
  return pts;
}

// Where in normalised device coordinates the framed hull may lie: the
// overlay's corner left free when there is one.
struct FitBox { double x_lo, x_hi, y_lo, y_hi; };

// Lookat and distance of a free camera at (azimuth, elevation) that shows
// every point inside `box` (perspective projection, fovy of the model).
void fit_camera(const std::vector<std::array<double, 3>>& pts, double azimuth_deg, double elevation_deg, double fovy_deg,
                double aspect, const FitBox& box, double lookat[3], double* distance) {
  const double az = azimuth_deg * std::numbers::pi / 180, el = elevation_deg * std::numbers::pi / 180;
  const double f[3] = {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
  const double up[3] = {-std::sin(el) * std::cos(az), -std::sin(el) * std::sin(az), std::cos(el)};
  double right[3];
  mju_cross(right, f, up);
  const double ty = std::tan(0.5 * fovy_deg * std::numbers::pi / 180), tx = ty * aspect;
  for (int i = 0; i < 3; ++i) {
    lookat[i] = 0;
    for (const auto& p : pts) lookat[i] += p[i] / static_cast<double>(pts.size());
  }
  auto extent = [&](double dist, double ndc[4]) {
    ndc[0] = ndc[2] = 1e9;
    ndc[1] = ndc[3] = -1e9;
    for (const auto& p : pts) {
      const double rel[3] = {p[0] - (lookat[0] - dist * f[0]), p[1] - (lookat[1] - dist * f[1]), p[2] - (lookat[2] - dist * f[2])};
      const double z = std::max(mju_dot3(rel, f), 1e-6);
      const double x = mju_dot3(rel, right) / (z * tx), y = mju_dot3(rel, up) / (z * ty);
      ndc[0] = std::min(ndc[0], x);
      ndc[1] = std::max(ndc[1], x);
      ndc[2] = std::min(ndc[2], y);
      ndc[3] = std::max(ndc[3], y);
    }
  };
  auto fits = [&](double dist) {
    double e[4];
    extent(dist, e);
    return e[1] - e[0] <= box.x_hi - box.x_lo && e[3] - e[2] <= box.y_hi - box.y_lo;
  };
  double dist = 0.1;
  for (int pass = 0; pass < 4; ++pass) {
    double lo = 1e-3, hi = 50;
    for (int it = 0; it < 50; ++it) {
      const double mid = 0.5 * (lo + hi);
      (fits(mid) ? hi : lo) = mid;
    }
    dist = hi;
    // Centre the projected hull in the box: move the lookat sideways.
    double e[4];
    extent(dist, e);
    const double dx = 0.5 * (e[0] + e[1]) - 0.5 * (box.x_lo + box.x_hi);
    const double dy = 0.5 * (e[2] + e[3]) - 0.5 * (box.y_lo + box.y_hi);
    for (int i = 0; i < 3; ++i) lookat[i] += dx * dist * tx * right[i] + dy * dist * ty * up[i];
  }
  *distance = dist;
}

} // namespace

struct OffscreenRenderer::Impl {
  RenderOptions options;
  CameraSpec spec;
  OSMesaContext osmesa = nullptr;
  std::vector<unsigned char> osmesa_buffer;
  mjvScene scn{};
  mjrContext con{};
  mjvCamera cam{};
  mjvOption opt{};
  int flange_jnt = -1;
  int led_geom = -1;
  int housing_geom = -1; // the degree scale lies on its top face
  int collar_geom = -1;
  int ghost_body = -1;
  int ghost_mocap = -1;
  bool framed = false;
  bool sky_decided = false; // with the framing: see planes_fill_view()
  // redraw_changed_only: the image holds the last frame (no title card);
  // the box that can change (pixels, origin bottom-left) and the overlay
  // rectangles the last frame drew.
  bool retained = false;
  std::optional<mjrRect> scene_box;
  mjrRect last_panel{0, 0, 0, 0}, last_banner{0, 0, 0, 0}, last_caption{0, 0, 0, 0};
  std::unique_ptr<FrameText> text; // overlay, banner, title card (on con)

  void make_current() {
    if (!OSMesaMakeCurrent(osmesa, osmesa_buffer.data(), GL_UNSIGNED_BYTE, options.width_px, options.height_px)) {
      throw std::runtime_error("OSMesaMakeCurrent failed");
    }
  }

  // Normalised-device box the module may fill: right of the overlay panel
  // and below the banner.
  FitBox fit_box(const SceneState& state) const {
    if (!options.leave_overlay_room || state.overlay.empty()) return {-0.9, 0.9, -0.9, 0.9};
    const OverlayPanel p = text->panel(state);
    const double w = options.width_px, h = options.height_px;
    const double right_px = p.x + p.width + 0.5 * p.char_height;
    const double banner_px = (text->banner_big() ? con.charHeightBig : con.charHeight) + 0.75 * con.charHeight;
    return {std::min(0.2, -1.0 + 2.0 * right_px / w), 0.94, -0.94, std::max(-0.2, 1.0 - 2.0 * banner_px / h)};
  }

  void frame_camera(const mjModel* m, const mjData* d, const SceneState& state) {
    if (!spec.model_camera.empty()) {
      const int id = mj_name2id(m, mjOBJ_CAMERA, spec.model_camera.c_str());
      if (id < 0) throw std::invalid_argument("the model has no camera named '" + spec.model_camera + "'");
      cam.type = mjCAMERA_FIXED;
      cam.fixedcamid = id;
      framed = true;
      return;
    }
    const bool top = spec.preset == CameraSpec::Preset::Top;
    cam.type = mjCAMERA_FREE;
    cam.azimuth = spec.azimuth_deg.value_or(top ? 90.0 : 135.0);
    cam.elevation = spec.elevation_deg.value_or(top ? -90.0 : -30.0);
    const double aspect = static_cast<double>(options.width_px) / options.height_px;
    // With an overlay the module keeps right of the text column and below
    // the banner (A-RENDERS-1).
    const FitBox box = fit_box(state);
    double lookat[3], distance = 0;
    fit_camera(hull_points(m, d, flange_jnt, ghost_body), cam.azimuth, top ? -89.9 : cam.elevation, m->vis.global.fovy,
               aspect, box, lookat, &distance);
    cam.distance = spec.distance_m.value_or(distance);
    for (int i = 0; i < 3; ++i) cam.lookat[i] = spec.lookat_m ? (*spec.lookat_m)[i] : lookat[i];
    framed = true;
  }

  // The setpoint ghost and the actual-position pointer (A-RENDERS-7): the
  // ghost body's geoms turned about the flange axis from their model pose,
  // lifted onto the top of the load so a load never hides them. Posed in
  // the scene only: d stays the twin's, untouched.
  void place_pointers(const mjModel* m, const mjData* d, std::optional<double> ghost_rad, bool labels) {
    if (ghost_mocap < 0 || flange_jnt < 0) return;
    const double* a = d->xanchor + 3 * flange_jnt;
    const double* u = d->xaxis + 3 * flange_jnt;
    const double sign = u[2] >= 0 ? 1.0 : -1.0;
    const double up[3] = {sign * u[0], sign * u[1], sign * u[2]};
    const double top = rotating_top(m, d, flange_jnt, up);
    const double* body_pos = m->body_pos + 3 * ghost_body;
    const double body_rel[3] = {body_pos[0] - a[0], body_pos[1] - a[1], body_pos[2] - a[2]};
    const double lift = std::max(0.0, top - mju_dot3(body_rel, up));

    auto pose = [&](double angle, double extra_lift, mjvGeom& g) {
      double q_rot[4], rel_rot[3], quat[4], gpos[3], gquat[4], gmat[9];
      mju_axisAngle2Quat(q_rot, u, angle);
      mju_rotVecQuat(rel_rot, body_rel, q_rot);
      mju_mulQuat(quat, q_rot, m->body_quat + 4 * ghost_body);
      mju_rotVecQuat(gpos, m->geom_pos + 3 * g.objid, quat);
      mju_mulQuat(gquat, quat, m->geom_quat + 4 * g.objid);
      mju_quat2Mat(gmat, gquat);
      for (int k = 0; k < 3; ++k) g.pos[k] = static_cast<float>(a[k] + rel_rot[k] + gpos[k] + (lift + extra_lift) * up[k]);
      for (int k = 0; k < 9; ++k) g.mat[k] = static_cast<float>(gmat[k]);
    };
    const int n = scn.ngeom;
    const double flange_rad = flange_angle_rad(m, d);
    // Labels at the tips (issue 29): one when the two pointers overlap.
    const bool apart = std::abs(ghost_rad.value_or(flange_rad) - flange_rad) > 8.0 * std::numbers::pi / 180.0;
    for (int i = 0; i < n; ++i) {
      if (scn.geoms[i].objtype != mjOBJ_GEOM || m->geom_bodyid[scn.geoms[i].objid] != ghost_body) continue;
      // The actual-position pointer: an opaque copy at the flange angle.
      if (scn.ngeom < scn.maxgeom) {
        mjvGeom& actual = scn.geoms[scn.ngeom++];
        actual = scn.geoms[i];
        pose(flange_rad, 0.0005, actual); // reads the model geom through objid
        actual.objtype = mjOBJ_UNKNOWN;   // then a decor geom, not the ghost
        actual.objid = -1;
        actual.segid = -1;
        // Bright orange, the flange mark's colour: an asymmetric marker on
        // every load so that rotation is visible (issue 16).
        const float mark[4] = {0.98f, 0.45f, 0.02f, 1.0f};
        std::copy(mark, mark + 4, actual.rgba);
        actual.transparent = 0;
        actual.emission = 0.25f;
        const bool tip = m->geom_type[scn.geoms[i].objid] == mjGEOM_SPHERE;
        std::snprintf(actual.label, sizeof actual.label, "%s", labels && tip ? (apart ? "flange" : "flange = setpoint") : "");
      }
      // The ghost sits just above the pointer so both stay visible.
      const bool tip = m->geom_type[scn.geoms[i].objid] == mjGEOM_SPHERE;
      std::snprintf(scn.geoms[i].label, sizeof scn.geoms[i].label, "%s", labels && tip && apart ? "setpoint" : "");
      pose(ghost_rad.value_or(flange_rad), 0.0015, scn.geoms[i]);
    }
  }

  // Everything that turns, moves or changes colour lies in the hull of
  // hull_points (rotation-invariant): its bounding box on screen, widened
  // for the labels written right of and above their anchors. Fixed once
  // the camera is.
  mjrRect changing_box(const mjModel* m, const mjData* d) {
    if (scene_box) return *scene_box;
    // The camera MuJoCo renders a mono image with: the two eyes averaged
    // (each eye sits half the interpupillary distance to the side).
    const mjvGLCamera c = mjv_averageCamera(&scn.camera[0], &scn.camera[1]);
    double right[3];
    const double fwd[3] = {c.forward[0], c.forward[1], c.forward[2]}, up[3] = {c.up[0], c.up[1], c.up[2]};
    mju_cross(right, fwd, up);
    const double w = options.width_px, h = options.height_px;
    const double px = (c.frustum_top - c.frustum_bottom) / h; // frustum units per pixel at the near plane
    const double left = c.frustum_center - 0.5 * px * w;
    double x0 = w, x1 = 0, y0 = h, y1 = 0;
    for (const auto& p : hull_points(m, d, flange_jnt, ghost_body)) {
      const double rel[3] = {p[0] - c.pos[0], p[1] - c.pos[1], p[2] - c.pos[2]};
      const double z = std::max(mju_dot3(rel, fwd), 1e-6);
      const double x = (mju_dot3(rel, right) * c.frustum_near / z - left) / px;
      const double y = (mju_dot3(rel, up) * c.frustum_near / z - c.frustum_bottom) / px;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    const int ch = con.charHeight;
    const int l = std::clamp(static_cast<int>(x0) - ch, 0, options.width_px);
    const int r = std::clamp(static_cast<int>(x1) + text->text_width("flange = setpoint", false) + ch, 0, options.width_px);
    const int b = std::clamp(static_cast<int>(y0) - ch, 0, options.height_px);
    const int t = std::clamp(static_cast<int>(y1) + 2 * ch, 0, options.height_px);
    scene_box = mjrRect{l, b, std::max(0, r - l), std::max(0, t - b)};
    return *scene_box;
  }

  // Renders only `box` of the frame: the camera's frustum narrowed to it,
  // so the pixels match the full frame's (issue 31).
  void render_box(const mjrRect& box) {
    if (box.width <= 0 || box.height <= 0) return;
    mjvGLCamera full[2] = {scn.camera[0], scn.camera[1]};
    for (int e = 0; e < 2; ++e) {
      mjvGLCamera& c = scn.camera[e];
      const float px = (full[e].frustum_top - full[e].frustum_bottom) / static_cast<float>(options.height_px);
      c.frustum_bottom = full[e].frustum_bottom + px * static_cast<float>(box.bottom);
      c.frustum_top = full[e].frustum_bottom + px * static_cast<float>(box.bottom + box.height);
      c.frustum_center = full[e].frustum_center + px * (static_cast<float>(box.left) + 0.5f * static_cast<float>(box.width) -
                                                         0.5f * static_cast<float>(options.width_px));
    }
    mjr_render(box, &scn, &con);
    scn.camera[0] = full[0];
    scn.camera[1] = full[1];
  }


  // The part of the frame that can differ from the last one: the changing
  // box, and where the last frame's opaque panel or banner stood but this
  // frame's does not cover (a narrower panel, another banner text).
  void render_changed(const mjModel* m, const mjData* d, const SceneState& state) {
    render_box(changing_box(m, d));
    for (const auto& [last, now] : {std::pair{last_panel, text->panel_rect(state)}, {last_banner, text->banner_rect(state.banner)},
                                    {last_caption, text->caption_rect(state)}}) {
      if (!covers(now, last)) render_box(last);
    }
  }

  static bool covers(const mjrRect& outer, const mjrRect& inner) {
    if (inner.width <= 0 || inner.height <= 0) return true;
    return inner.left >= outer.left && inner.bottom >= outer.bottom && inner.left + inner.width <= outer.left + outer.width &&
           inner.bottom + inner.height <= outer.bottom + outer.height;
  }

  void paint_led(LedColor c) {
    if (led_geom < 0) return;
    const LedLook look = led_look(c);
    for (int i = 0; i < scn.ngeom; ++i) {
      mjvGeom& g = scn.geoms[i];
      if (g.objtype != mjOBJ_GEOM || g.objid != led_geom) continue;
      std::copy(look.rgba.begin(), look.rgba.end(), g.rgba);
      g.emission = look.emission;
    }
  }

};

OffscreenRenderer::OffscreenRenderer(const mjModel* m, const RenderOptions& options, const CameraSpec& camera)
    : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  if (options.width_px < 16 || options.height_px < 16 || options.width_px % 2 || options.height_px % 2) {
    throw std::invalid_argument("render size must be even and at least 16x16");
  }
  s.options = options;
  s.spec = camera;
  s.osmesa = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 8, nullptr);
  if (!s.osmesa) throw std::runtime_error("OSMesaCreateContextExt failed");
  s.osmesa_buffer.resize(static_cast<std::size_t>(options.width_px) * static_cast<std::size_t>(options.height_px) * 4);
  try {
    s.make_current();
  } catch (...) {
    OSMesaDestroyContext(s.osmesa);
    throw;
  }

  // 2.2.2 sizes the offscreen buffer from the model at mjr_makeContext and
  // cannot resize it later: set the size on a private copy of the model.
  mjModel* sized = mj_copyModel(nullptr, m);
  sized->vis.global.offwidth = options.width_px;
  sized->vis.global.offheight = options.height_px;
  sized->vis.quality.offsamples = options.msaa_samples;
  sized->vis.quality.shadowsize = options.shadow_size;
  mjr_defaultContext(&s.con);
  mjr_makeContext(sized, &s.con, font_scale_for(options.height_px));
  mj_deleteModel(sized);
  // 2D textures (the table's checker) sample one mipmap level instead of
  // blending two: 5 of ~45 ms of CPU per 720p frame on llvmpipe, no
  // visible difference on a checker seen at a slant (issue 31).
  for (int t = 0; t < m->ntex; ++t) {
    if (m->tex_type[t] != mjTEXTURE_2D) continue;
    glBindTexture(GL_TEXTURE_2D, s.con.texture[t]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  }
  mjr_setBuffer(mjFB_OFFSCREEN, &s.con);
  if (s.con.currentBuffer != mjFB_OFFSCREEN || s.con.offWidth != options.width_px || s.con.offHeight != options.height_px) {
    mjr_freeContext(&s.con);
    OSMesaDestroyContext(s.osmesa);
    throw std::runtime_error("MuJoCo could not make an offscreen buffer of the requested size");
  }

  s.text = std::make_unique<FrameText>(s.con, options.width_px, options.height_px);
  mjv_defaultScene(&s.scn);
  mjv_makeScene(m, &s.scn, 2000);
  mjv_defaultOption(&s.opt);
  mjv_defaultCamera(&s.cam);
  s.scn.flags[mjRND_SHADOW] = options.shadows ? 1 : 0;
  s.scn.flags[mjRND_REFLECTION] = options.reflections ? 1 : 0;

  s.flange_jnt = mj_name2id(m, mjOBJ_JOINT, "flange");
  s.led_geom = mj_name2id(m, mjOBJ_GEOM, "led_band");
  s.housing_geom = mj_name2id(m, mjOBJ_GEOM, "housing");
  s.collar_geom = mj_name2id(m, mjOBJ_GEOM, "collar");
  s.ghost_body = mj_name2id(m, mjOBJ_BODY, "setpoint_ghost");
  if (s.ghost_body >= 0) s.ghost_mocap = m->body_mocapid[s.ghost_body];
}

OffscreenRenderer::~OffscreenRenderer() {
  Impl& s = *impl_;
  OSMesaMakeCurrent(s.osmesa, s.osmesa_buffer.data(), GL_UNSIGNED_BYTE, s.options.width_px, s.options.height_px);
  mjv_freeScene(&s.scn);
  mjr_freeContext(&s.con);
  // Unbind first: Mesa frees the framebuffer MakeCurrent made only on unbind.
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(s.osmesa);
}

void OffscreenRenderer::set_camera(const CameraSpec& camera) {
  impl_->spec = camera;
  impl_->framed = false;
  impl_->sky_decided = false;
  impl_->scn.flags[mjRND_SKYBOX] = 1;
  impl_->retained = false;
  impl_->scene_box.reset();
}

int OffscreenRenderer::width() const { return impl_->options.width_px; }
int OffscreenRenderer::height() const { return impl_->options.height_px; }
OverlayPanel OffscreenRenderer::overlay_panel(const SceneState& state) const { return impl_->text->panel(state); }
const std::vector<DrawnText>& OffscreenRenderer::drawn_text() const { return impl_->text->drawn(); }

void OffscreenRenderer::render_into(const mjModel* m, const mjData* d, const SceneState& state, uint8_t* rgb, bool flip) {
  Impl& s = *impl_;
  s.make_current();
  mjr_setBuffer(mjFB_OFFSCREEN, &s.con);
  if (!s.framed) s.frame_camera(m, d, state);
  // 2.2.2's mjv_updateScene takes mjData* but only reads it.
  mjv_updateScene(m, const_cast<mjData*>(d), &s.opt, nullptr, &s.cam, mjCAT_ALL, &s.scn);
  set_clip_planes(s.scn);
  if (!s.sky_decided) {
    if (planes_fill_view(m, d, s.scn, static_cast<double>(s.options.width_px) / s.options.height_px)) s.scn.flags[mjRND_SKYBOX] = 0;
    s.sky_decided = true;
  }
  s.place_pointers(m, d, state.ghost_joint_rad, state.pointer_labels);
  if (state.degree_scale) {
    add_degree_scale(m, d, s.scn, SceneIds{s.flange_jnt, s.housing_geom, s.collar_geom, s.ghost_body}, state.ghost_joint_rad,
                     state.pointer_labels);
  }
  s.paint_led(state.led);
  const mjrRect viewport{0, 0, s.options.width_px, s.options.height_px};
  const bool partial = s.options.redraw_changed_only && !s.options.shadows && !s.options.reflections && s.flange_jnt >= 0;
  // A full frame first where the image holds no last frame; its changing
  // parts are then drawn as every later frame draws them, so that frames of
  // the same state are pixel-identical (coplanar faces may resolve their
  // depth ties differently under the narrowed frustum).
  if (!partial || !s.retained) mjr_render(viewport, &s.scn, &s.con);
  if (partial) s.render_changed(m, d, state);
  s.text->clear_drawn();
  if (state.title) {
    s.text->draw_title(*state.title);
  } else {
    s.text->draw_panel(state);
    s.text->draw_caption(state);
    s.text->draw_banner(state.banner);
  }
  // The image now holds this frame's overlay: the next frame redraws under it.
  s.retained = !state.title;
  s.last_panel = s.text->panel_rect(state);
  s.last_banner = s.text->banner_rect(state.banner);
  s.last_caption = s.text->caption_rect(state);
  mjr_readPixels(rgb, nullptr, viewport, &s.con);
  if (flip) flip_rows(rgb, s.options.width_px, s.options.height_px);
}

RgbImage OffscreenRenderer::render(const mjModel* m, const mjData* d, const SceneState& state) {
  RgbImage img;
  img.width = impl_->options.width_px;
  img.height = impl_->options.height_px;
  img.rgb.resize(static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height) * 3);
  render_into(m, d, state, img.rgb.data(), true);
  return img;
}

} // namespace sreh
