#include "renders/offscreen_text.hpp"

#include <algorithm>
#include <vector>

namespace sreh {

namespace {
// The widest value the overlay's value column is sized for whatever the
// frame shows, so that the panel keeps its width through a run.
constexpr const char* kValueTemplate = "-000.00 deg";
} // namespace

// Font scale by image height (issue 29): the largest MuJoCo scale whose
// normal font (18 px at 100 %, 2.2.2 has no smaller one) is at most 4 % of
// the frame height: 18 px up to 539 px, 28 px at 720, 37 px at 1080.
int font_scale_for(int height_px) {
  const int scale = 50 * static_cast<int>(height_px / 4.5 / 50.0);
  return std::clamp(scale, static_cast<int>(mjFONTSCALE_100), static_cast<int>(mjFONTSCALE_300));
}

int FrameText::text_width(const std::string& text, bool big) const {
  int w = 0;
  for (unsigned char c : text) w += c < 127 ? (big ? con_.charWidthBig[c] : con_.charWidth[c]) : 0;
  return w;
}

// The overlay panel (issue 29): every size a fraction of the normal
// font's height, which follows the frame height (font_scale_for). Rows
// with an empty label span both columns.
OverlayPanel FrameText::panel(const SceneState& state) const {
  OverlayPanel p;
  if (state.overlay.empty()) return p;
  const int ch = con_.charHeight;
  int labels = 0, values = text_width(kValueTemplate, false), spans = 0;
  for (const auto& [l, v] : state.overlay) {
    if (l.empty()) {
      spans = std::max(spans, text_width(v, false));
    } else {
      labels = std::max(labels, text_width(l, false));
      values = std::max(values, text_width(v, false));
    }
  }
  p.x = p.y = ch / 4;
  p.width = 2 * (ch / 3) + std::max(labels + ch / 3 + values, spans);
  p.height = 2 * (ch / 3) + static_cast<int>(state.overlay.size()) * row_pitch();
  p.char_height = ch;
  return p;
}
int FrameText::row_pitch() const { return con_.charHeight + con_.charHeight / 6; }
// The banner's font: big where it stays under 8 % of the frame height.
bool FrameText::banner_big() const { return con_.charHeightBig <= 0.08 * height_px_; }

// The overlay's rectangles in GL pixels (origin bottom-left).
mjrRect FrameText::panel_rect(const SceneState& state) const {
  const OverlayPanel p = panel(state);
  return {p.x, height_px_ - p.y - p.height, p.width, p.height};
}
mjrRect FrameText::banner_rect(const std::string& banner) const {
  if (banner.empty()) return {0, 0, 0, 0};
  const bool big = banner_big();
  const int ch = con_.charHeight, h = (big ? con_.charHeightBig : con_.charHeight) + 2 * (ch / 4);
  const int w = text_width(banner, big) + 2 * (ch / 3);
  return {width_px_ - w - ch / 3, height_px_ - ch / 3 - h, w, h};
}

// Text at pixel (x, y_top) of the frame (origin top-left): mjr_text
// places relative to the last viewport, set here by an empty rectangle
// the size of the text (the raster position must lie inside it).
void FrameText::text_at(const char* kind, int font, const std::string& txt, int x, int y_top, const float rgb[3]) const {
  if (txt.empty()) return;
  const bool big = font == mjFONT_BIG;
  const int h = big ? con_.charHeightBig : con_.charHeight;
  drawn_.push_back({kind, x, y_top, text_width(txt, big), h, txt});
  mjr_rectangle(mjrRect{x, height_px_ - y_top - h, text_width(txt, big) + 1, h}, 0, 0, 0, 0);
  // The raster position is the glyphs' baseline: a fifth of the height up.
  mjr_text(font, txt.c_str(), &con_, 0.0f, 0.2f, rgb[0], rgb[1], rgb[2]);
}

void FrameText::draw_panel(const SceneState& state) const {
  const OverlayPanel p = panel(state);
  if (p.width == 0) return;
  // Opaque: what lies under it need not be redrawn each frame (A-RENDERS-18).
  mjr_rectangle(mjrRect{p.x, height_px_ - p.y - p.height, p.width, p.height}, 0.22f, 0.23f, 0.25f, 1.0f);
  const int ch = con_.charHeight, pad = ch / 3;
  int labels = 0;
  for (const auto& [l, v] : state.overlay) labels = std::max(labels, text_width(l, false));
  const float label_rgb[3] = {0.72f, 0.75f, 0.78f}, value_rgb[3] = {1, 1, 1};
  int y = p.y + pad;
  for (const auto& [l, v] : state.overlay) {
    if (l.empty()) {
      text_at("panel", mjFONT_NORMAL, v, p.x + pad, y, value_rgb);
    } else {
      text_at("panel", mjFONT_NORMAL, l, p.x + pad, y, label_rgb);
      text_at("panel", mjFONT_NORMAL, v, p.x + pad + labels + ch / 3, y, value_rgb);
    }
    y += row_pitch();
  }
}

void FrameText::draw_banner(const std::string& banner) const {
  if (banner.empty()) return;
  const bool big = banner_big();
  const int font = big ? mjFONT_BIG : mjFONT_NORMAL;
  const int ch = con_.charHeight, h = big ? con_.charHeightBig : con_.charHeight;
  const int w = text_width(banner, big) + 2 * (ch / 3), x = width_px_ - w - ch / 3, y = ch / 3;
  mjr_rectangle(mjrRect{x, height_px_ - y - h - 2 * (ch / 4), w, h + 2 * (ch / 4)}, 0.22f, 0.23f, 0.25f, 1.0f);
  const float rgb[3] = {1, 1, 1};
  text_at("banner", font, banner, x + ch / 3, y + ch / 4, rgb);
}

std::vector<std::string> FrameText::wrap(const std::string& text, bool big, int max_w) const {
  std::vector<std::string> lines;
  std::string line;
  auto fits = [&](const std::string& t) { return text_width(t, big) <= max_w; };
  std::size_t i = 0;
  while (i < text.size()) {
    std::size_t end = text.find(' ', i);
    if (end == std::string::npos) end = text.size();
    std::string word = text.substr(i, end - i);
    i = end + 1;
    if (word.empty()) continue;
    if (fits(line.empty() ? word : line + " " + word)) {
      line = line.empty() ? word : line + " " + word;
      continue;
    }
    if (!line.empty()) lines.push_back(line);
    line.clear();
    // A word wider than the line: broken between characters.
    while (!fits(word) && word.size() > 1) {
      std::size_t n = 1;
      while (n < word.size() && fits(word.substr(0, n + 1))) ++n;
      lines.push_back(word.substr(0, n));
      word.erase(0, n);
    }
    line = word;
  }
  if (!line.empty() || lines.empty()) lines.push_back(line);
  return lines;
}

// The caption (issue 39): in the overlay's column right below the panel,
// wrapped to the panel's width; the module keeps right of that column.
std::vector<std::string> FrameText::caption_lines(const SceneState& state) const {
  if (state.caption.empty()) return {};
  const OverlayPanel p = panel(state);
  const int ch = con_.charHeight;
  const int inner = (p.width > 0 ? p.width : width_px_ / 4) - 2 * (ch / 3);
  return wrap(state.caption, false, inner);
}
mjrRect FrameText::caption_rect(const SceneState& state) const {
  const std::vector<std::string> lines = caption_lines(state);
  if (lines.empty()) return {0, 0, 0, 0};
  const OverlayPanel p = panel(state);
  const int ch = con_.charHeight;
  const int w = p.width > 0 ? p.width : width_px_ / 4; // the module keeps right of the panel (fit_box)
  const int top = p.y + p.height + ch / 4;
  const int h = 2 * (ch / 3) + static_cast<int>(lines.size()) * row_pitch();
  return {p.x, height_px_ - top - h, w, h};
}
void FrameText::draw_caption(const SceneState& state) const {
  const std::vector<std::string> lines = caption_lines(state);
  if (lines.empty()) return;
  const mjrRect r = caption_rect(state);
  mjr_rectangle(r, 0.16f, 0.20f, 0.30f, 1.0f);
  const int ch = con_.charHeight;
  const float rgb[3] = {1.0f, 0.93f, 0.6f};
  int y = height_px_ - r.bottom - r.height + ch / 3;
  for (const std::string& line : lines) {
    text_at("caption", mjFONT_NORMAL, line, r.left + ch / 3, y, rgb);
    y += row_pitch();
  }
}

// A card (the title card, the closing card): the frame dimmed, the heading
// in the big font (the normal one where the card would not fit the frame
// otherwise), the lines as two centred columns; every text wrapped at
// spaces, never cut (issue 39).
void FrameText::draw_title(const TitleCard& card) const {
  const int w = width_px_, h = height_px_, ch = con_.charHeight;
  mjr_rectangle(mjrRect{0, 0, w, h}, 0.05f, 0.06f, 0.07f, 0.78f);
  const int max_w = w - 2 * ch;
  int labels = 0, values = 0;
  for (const auto& [l, v] : card.lines) {
    labels = std::max(labels, text_width(l, false));
    values = std::max(values, text_width(v, false));
  }
  values = std::max(ch, std::min(values, max_w - labels - ch));
  std::vector<std::pair<std::string, std::string>> rows; // the lines, values wrapped
  for (const auto& [l, v] : card.lines) {
    bool first = true;
    for (const std::string& part : wrap(v, false, values)) {
      rows.emplace_back(first ? l : std::string(), part);
      first = false;
    }
  }
  const int rows_h = ch + static_cast<int>(rows.size()) * row_pitch();
  bool big = con_.charHeightBig <= 0.12 * h;
  std::vector<std::string> heading = wrap(card.heading, big, max_w);
  if (big && static_cast<int>(heading.size()) * con_.charHeightBig + rows_h > h - ch) {
    big = false;
    heading = wrap(card.heading, false, max_w);
  }
  const int heading_h = big ? con_.charHeightBig : con_.charHeight;
  const int block_h = static_cast<int>(heading.size()) * heading_h + rows_h;
  int y = std::max(ch / 2, (h - block_h) / 2);
  const float grey[3] = {0.72f, 0.75f, 0.78f}, white[3] = {1, 1, 1};
  const float heading_rgb[3] = {card.heading_rgb[0], card.heading_rgb[1], card.heading_rgb[2]};
  for (const std::string& line : heading) {
    text_at("card", big ? mjFONT_BIG : mjFONT_NORMAL, line, (w - text_width(line, big)) / 2, y, heading_rgb);
    y += heading_h;
  }
  y += ch;
  const int x0 = std::max(ch, (w - labels - ch - values) / 2);
  for (const auto& [l, v] : rows) {
    if (!l.empty()) text_at("card", mjFONT_NORMAL, l, x0, y, grey);
    text_at("card", mjFONT_NORMAL, v, x0 + labels + ch, y, white);
    y += row_pitch();
  }
}

} // namespace sreh
