// OSMesa + MuJoCo off-screen renderer (design/mujoco.md "Rendering off-screen").
#include "renders/offscreen.hpp"

#include <GL/osmesa.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <stdexcept>

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

// Font scale for the overlay by image height (mjtFontScale steps of 50).
int font_scale_for(int height_px) {
  if (height_px <= 480) return mjFONTSCALE_100;
  if (height_px <= 800) return mjFONTSCALE_150;
  return mjFONTSCALE_200;
}

struct Framing { double center[3]; double radius; };

// Bounding cylinder about the flange axis of every visible non-plane geom:
// invariant under flange rotation, so the camera does not breathe with an
// off-centre load (A-RENDERS-1). Falls back to MuJoCo's model statistics.
Framing frame_module(const mjModel* m, const mjData* d, int flange_jnt) {
  Framing f{{m->stat.center[0], m->stat.center[1], m->stat.center[2]}, m->stat.extent};
  if (flange_jnt < 0) return f;
  const double* a = d->xanchor + 3 * flange_jnt;
  const double* u = d->xaxis + 3 * flange_jnt;
  double r_max = 0, h_min = std::numeric_limits<double>::max(), h_max = -h_min;
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_type[g] == mjGEOM_PLANE || m->geom_group[g] > 2) continue;
    const double* p = d->geom_xpos + 3 * g;
    const double rel[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    const double h = mju_dot3(rel, u);
    const double radial[3] = {rel[0] - h * u[0], rel[1] - h * u[1], rel[2] - h * u[2]};
    const double rb = m->geom_rbound[g];
    r_max = std::max(r_max, mju_norm3(radial) + rb);
    h_min = std::min(h_min, h - rb);
    h_max = std::max(h_max, h + rb);
  }
  if (h_min > h_max) return f;
  const double hc = 0.5 * (h_min + h_max);
  for (int i = 0; i < 3; ++i) f.center[i] = a[i] + hc * u[i];
  const double half_h = 0.5 * (h_max - h_min);
  f.radius = std::sqrt(r_max * r_max + half_h * half_h);
  return f;
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
  int ghost_body = -1;
  int ghost_mocap = -1;
  bool framed = false;

  void make_current() {
    if (!OSMesaMakeCurrent(osmesa, osmesa_buffer.data(), GL_UNSIGNED_BYTE, options.width_px, options.height_px)) {
      throw std::runtime_error("OSMesaMakeCurrent failed");
    }
  }

  void frame_camera(const mjModel* m, const mjData* d) {
    const Framing f = frame_module(m, d, flange_jnt);
    const double half_fov = 0.5 * m->vis.global.fovy * std::numbers::pi / 180.0;
    const double aspect = static_cast<double>(options.width_px) / options.height_px;
    // Fit the bounding sphere into the narrower of the two fields of view.
    const double half_fit = std::min(half_fov, std::atan(std::tan(half_fov) * aspect));
    const double fit_distance = 0.95 * f.radius / std::sin(half_fit); // A-RENDERS-1 margin
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
    cam.elevation = spec.elevation_deg.value_or(top ? -90.0 : -25.0);
    cam.distance = spec.distance_m.value_or(fit_distance);
    for (int i = 0; i < 3; ++i) cam.lookat[i] = spec.lookat_m ? (*spec.lookat_m)[i] : f.center[i];
    framed = true;
  }

  // Height along the module's up direction (the flange axis, pointing away
  // from the table) of the top of everything that turns with the flange.
  static double axial_half_extent(const mjModel* m, const mjData* d, int g, const double* up) {
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

  // The setpoint ghost and the actual-position pointer (A-RENDERS-7): the
  // ghost body's geoms turned about the flange axis from their model pose,
  // lifted onto the top of the load so a load never hides them. Posed in
  // the scene only: d stays the twin's, untouched.
  void place_pointers(const mjModel* m, const mjData* d, std::optional<double> ghost_rad) {
    if (ghost_mocap < 0 || flange_jnt < 0) return;
    const double* a = d->xanchor + 3 * flange_jnt;
    const double* u = d->xaxis + 3 * flange_jnt;
    const double sign = u[2] >= 0 ? 1.0 : -1.0;
    const double up[3] = {sign * u[0], sign * u[1], sign * u[2]};
    const int root = m->body_rootid[m->jnt_bodyid[flange_jnt]];
    double top = -std::numeric_limits<double>::max();
    for (int g = 0; g < m->ngeom; ++g) {
      if (m->body_rootid[m->geom_bodyid[g]] != root || m->geom_group[g] > 2) continue;
      const double* p = d->geom_xpos + 3 * g;
      const double rel[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
      top = std::max(top, mju_dot3(rel, up) + axial_half_extent(m, d, g, up));
    }
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
    const double flange_rad = d->qpos[m->jnt_qposadr[flange_jnt]];
    for (int i = 0; i < n; ++i) {
      if (scn.geoms[i].objtype != mjOBJ_GEOM || m->geom_bodyid[scn.geoms[i].objid] != ghost_body) continue;
      // The actual-position pointer: an opaque dark copy at the flange angle
      // (manual 3.5.2 Fig. 3 draws the actual position black).
      if (scn.ngeom < scn.maxgeom) {
        mjvGeom& actual = scn.geoms[scn.ngeom++];
        actual = scn.geoms[i];
        pose(flange_rad, 0.0005, actual); // reads the model geom through objid
        actual.objtype = mjOBJ_UNKNOWN;   // then a decor geom, not the ghost
        actual.objid = -1;
        actual.segid = -1;
        const float dark[4] = {0.08f, 0.08f, 0.09f, 1.0f};
        std::copy(dark, dark + 4, actual.rgba);
        actual.transparent = 0;
        actual.emission = 0;
      }
      // The ghost sits just above the pointer so both stay visible.
      pose(ghost_rad.value_or(flange_rad), 0.0015, scn.geoms[i]);
    }
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

  void draw_overlay(const SceneState& state, mjrRect viewport) {
    if (state.overlay.empty()) return;
    std::string labels, values;
    for (const auto& [label, value] : state.overlay) {
      if (!labels.empty()) { labels += '\n'; values += '\n'; }
      labels += label;
      values += value;
    }
    mjr_overlay(mjFONT_NORMAL, mjGRID_TOPLEFT, viewport, labels.c_str(), values.c_str(), &con);
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
  mjr_setBuffer(mjFB_OFFSCREEN, &s.con);
  if (s.con.currentBuffer != mjFB_OFFSCREEN || s.con.offWidth != options.width_px || s.con.offHeight != options.height_px) {
    mjr_freeContext(&s.con);
    OSMesaDestroyContext(s.osmesa);
    throw std::runtime_error("MuJoCo could not make an offscreen buffer of the requested size");
  }

  mjv_defaultScene(&s.scn);
  mjv_makeScene(m, &s.scn, 2000);
  mjv_defaultOption(&s.opt);
  mjv_defaultCamera(&s.cam);
  s.scn.flags[mjRND_SHADOW] = options.shadows ? 1 : 0;
  s.scn.flags[mjRND_REFLECTION] = options.reflections ? 1 : 0;

  s.flange_jnt = mj_name2id(m, mjOBJ_JOINT, "flange");
  s.led_geom = mj_name2id(m, mjOBJ_GEOM, "led_band");
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
}

int OffscreenRenderer::width() const { return impl_->options.width_px; }
int OffscreenRenderer::height() const { return impl_->options.height_px; }

void OffscreenRenderer::render_into(const mjModel* m, const mjData* d, const SceneState& state, uint8_t* rgb, bool flip) {
  Impl& s = *impl_;
  s.make_current();
  mjr_setBuffer(mjFB_OFFSCREEN, &s.con);
  if (!s.framed) s.frame_camera(m, d);
  // 2.2.2's mjv_updateScene takes mjData* but only reads it.
  mjv_updateScene(m, const_cast<mjData*>(d), &s.opt, nullptr, &s.cam, mjCAT_ALL, &s.scn);
  s.place_pointers(m, d, state.ghost_joint_rad);
  s.paint_led(state.led);
  const mjrRect viewport{0, 0, s.options.width_px, s.options.height_px};
  mjr_render(viewport, &s.scn, &s.con);
  s.draw_overlay(state, viewport);
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
