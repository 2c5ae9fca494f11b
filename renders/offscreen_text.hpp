// Text and panels drawn over a rendered frame with MuJoCo's fonts (issue
// 29): the overlay panel, the time-scale banner and the title card, every
// size a fraction of the normal font's height, which follows the frame
// height (A-RENDERS-10). Internal to renders/: used by OffscreenRenderer on
// its own GL context.
#pragma once
#include <mujoco/mujoco.h>

#include <string>
#include <vector>

#include "renders/offscreen.hpp"

namespace sreh {

// The MuJoCo font scale for a frame `height_px` high: the largest whose
// normal font is at most 4 % of the height.
int font_scale_for(int height_px);

class FrameText {
 public:
  // `con` must outlive this and be current when drawing.
  FrameText(const mjrContext& con, int width_px, int height_px) : con_(con), width_px_(width_px), height_px_(height_px) {}

  int text_width(const std::string& text, bool big) const;
  // The overlay panel (pixels, origin top-left) and, in GL pixels (origin
  // bottom-left), the rectangles the panel and the banner cover.
  OverlayPanel panel(const SceneState& state) const;
  mjrRect panel_rect(const SceneState& state) const;
  mjrRect banner_rect(const std::string& banner) const;
  mjrRect caption_rect(const SceneState& state) const;
  // The banner's font: big where it stays under 8 % of the frame height.
  bool banner_big() const;

  void draw_panel(const SceneState& state) const;
  void draw_banner(const std::string& banner) const;
  void draw_caption(const SceneState& state) const;
  void draw_title(const TitleCard& card) const;

  // `text` broken at spaces into lines at most `max_w` pixels wide (a word
  // wider than that is broken between characters): never cut.
  std::vector<std::string> wrap(const std::string& text, bool big, int max_w) const;
  // What the draw_* calls drew since the last clear.
  void clear_drawn() const { drawn_.clear(); }
  const std::vector<DrawnText>& drawn() const { return drawn_; }

 private:
  int row_pitch() const;
  void text_at(const char* kind, int font, const std::string& txt, int x, int y_top, const float rgb[3]) const;
  std::vector<std::string> caption_lines(const SceneState& state) const;

  const mjrContext& con_;
  int width_px_;
  int height_px_;
  mutable std::vector<DrawnText> drawn_;
};

} // namespace sreh
