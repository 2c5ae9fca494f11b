// Off-screen rendering of the module with OSMesa (issue 7, design/mujoco.md
// "Rendering off-screen"). One renderer owns one OSMesa context and one
// MuJoCo GPU context; every call makes its context current on the calling
// thread, so a renderer may be used from any (one at a time) thread.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "device_logic/device_types.hpp"

struct mjModel_;
struct mjData_;

namespace sreh {

// Where the camera looks from. Unset fields take the automatic framing of
// the module and its load (renders.md A-RENDERS-1).
struct CameraSpec {
  enum class Preset : uint8_t { Default, Top };
  Preset preset = Preset::Default;
  std::optional<double> azimuth_deg;
  std::optional<double> elevation_deg;
  std::optional<double> distance_m;
  std::optional<std::array<double, 3>> lookat_m;
  std::string model_camera; // non-empty: a fixed <camera> of the model by name (overrides the rest)

  static CameraSpec top() { CameraSpec c; c.preset = Preset::Top; return c; }
};

struct RenderOptions {
  int width_px = 1280;   // must be even (yuv420p video)
  int height_px = 720;
  int msaa_samples = 4;    // m->vis.quality.offsamples (A-RENDERS-3)
  bool shadows = false;    // off by default: 3x the render cost, jagged at 1024 (A-RENDERS-3)
  int shadow_size = 2048;  // shadow map texture size when shadows are on
  bool reflections = false; // reflective materials (e.g. the table) mirror the module
  bool leave_overlay_room = false; // automatic framing keeps clear of the overlay's corners
  // Video frames (issue 31): after a full first frame, redraw only the part
  // of the image that can change -- the module and load's box with room
  // for the labels, and the overlay's panel and banner -- and keep the rest
  // of the multisampled image from the frame before. Off with shadows or
  // reflections (they reach the table). A-RENDERS-18.
  bool redraw_changed_only = false;
};

// A video's opening card (issue 29): a heading (the scenario's name) and
// label/value lines (load, inertia, parameter sets, ...), drawn centred over
// the dimmed first frame with the overlay's fonts.
// The closing card (issue 39) is one too: the verdict as its heading, in
// the heading's colour, the failed checks and the final state as its lines.
// Text is wrapped at spaces to the frame's width, never cut.
struct TitleCard {
  std::string heading;
  std::vector<std::pair<std::string, std::string>> lines;
  std::array<float, 3> heading_rgb{1, 1, 1};
};

// One piece of text a frame shows and where (pixels, origin top-left): what
// the video's text log records (issue 39) so that tests and tools can read
// a frame's words without OCR.
struct DrawnText {
  std::string kind; // "panel", "banner", "caption", "card"
  int x = 0, y = 0, width = 0, height = 0;
  std::string text;
};

// What changes per frame besides the physics state.
struct SceneState {
  LedColor led = LedColor::Off;
  // Flange joint angle (MuJoCo qpos sense, rad) the setpoint ghost shows;
  // unset: the flange's own angle. Ghost and an opaque actual-position
  // pointer are drawn on top of the load (A-RENDERS-7).
  std::optional<double> ghost_joint_rad;
  // Text lines drawn in the top-left corner: label column, value column.
  std::vector<std::pair<std::string, std::string>> overlay;
  // Text in the top-right corner (the time scale: shown here once, not as
  // an overlay row too); big font from 720 px high, normal font below.
  std::string banner;
  // A scenario's `comment:` step while it applies (issue 39): drawn in the
  // overlay's column below the panel, wrapped to the panel's width.
  std::string caption;
  // Set: the frame is the title card (the overlay and banner are not drawn).
  std::optional<TitleCard> title;
  // The degree scale on the housing top and the labels on the flange
  // pointer and the setpoint ghost (issue 29, A-RENDERS-15).
  bool degree_scale = true;
  bool pointer_labels = true;
};

// Where the overlay panel lies (pixels, origin top-left) and its font, for a
// frame of the renderer's size: sized from the frame height (issue 29).
struct OverlayPanel {
  int x = 0, y = 0, width = 0, height = 0;
  int char_height = 0; // of the normal font: the MuJoCo font scale chosen by frame height
};

// An RGB image, rows top-down, 3 bytes per pixel.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgb;
  std::array<uint8_t, 3> at(int x, int y) const {
    const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

// The LED band colour as rendered (A-RENDERS-2): rgba and emission.
struct LedLook { std::array<float, 4> rgba; float emission; };
LedLook led_look(LedColor c);

class OffscreenRenderer {
 public:
  // The model's geometry is uploaded once; `m` must outlive the renderer and
  // keep its structure (same model, or one compiled from the same MJCF).
  // Throws std::runtime_error if OSMesa or MuJoCo cannot make the context.
  OffscreenRenderer(const mjModel_* m, const RenderOptions& options, const CameraSpec& camera = {});
  ~OffscreenRenderer();
  OffscreenRenderer(const OffscreenRenderer&) = delete;
  OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

  void set_camera(const CameraSpec& camera);

  // Renders the current state of `d` (kinematics as the last step left it).
  // `d` is only read: the ghost is posed in the scene, not in d->mocap_*.
  RgbImage render(const mjModel_* m, const mjData_* d, const SceneState& state);
  // Same, into a caller-owned buffer of width*height*3 bytes. With
  // `flip` false the rows stay bottom-up as OpenGL reads them.
  void render_into(const mjModel_* m, const mjData_* d, const SceneState& state, uint8_t* rgb, bool flip = true);

  int width() const;
  int height() const;
  // The panel `state.overlay` is drawn in (empty: zero size).
  OverlayPanel overlay_panel(const SceneState& state) const;
  // The text the last render drew, in drawing order.
  const std::vector<DrawnText>& drawn_text() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The flange's angle (MuJoCo sense, rad) in `d`: the sum of the hinges from
// the flange body to the world (rotor + compliance on the two-mass plant).
double flange_angle_rad(const mjModel_* m, const mjData_* d);

// Flips an RGB image with `height` rows of `width` pixels in place.
void flip_rows(uint8_t* rgb, int width, int height);

} // namespace sreh
