#include "renders/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace sreh::svg {

std::vector<double> nice_ticks(double lo, double hi, int max_ticks) {
  std::vector<double> ticks;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi) || max_ticks < 2) return ticks;
  const double raw = (hi - lo) / (max_ticks - 1);
  const int exponent = static_cast<int>(std::floor(std::log10(raw)));
  const double mag = std::pow(10.0, exponent);
  double factor = 10;
  for (double f : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    if (f * mag >= raw) {
      factor = f;
      break;
    }
  }
  const double step = factor * mag;
  // Tick i is i * step computed once (no accumulation); dividing by an exact
  // power of ten gives 0.6 rather than 3 * 0.2 = 0.6000000000000001.
  auto tick = [&](long i) {
    const double scaled = static_cast<double>(i) * factor;
    return exponent < 0 ? scaled / std::pow(10.0, -exponent) : scaled * mag;
  };
  const long first = static_cast<long>(std::ceil(lo / step - 1e-9));
  const long last = static_cast<long>(std::floor(hi / step + 1e-9));
  for (long i = first; i <= last; ++i) ticks.push_back(tick(i));
  return ticks;
}

std::vector<std::size_t> decimate_min_max(const std::vector<double>& x, const std::vector<double>& y, double x_lo,
                                          double x_hi, int columns) {
  std::vector<std::size_t> keep;
  const std::size_t n = std::min(x.size(), y.size());
  if (n == 0 || columns <= 0 || !(x_hi > x_lo)) return keep;
  const std::size_t begin = static_cast<std::size_t>(std::lower_bound(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(n), x_lo) - x.begin());
  const std::size_t end = static_cast<std::size_t>(std::upper_bound(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(n), x_hi) - x.begin());
  if (begin > 0) keep.push_back(begin - 1);
  if (end - begin <= static_cast<std::size_t>(4 * columns)) {
    for (std::size_t i = begin; i < end; ++i) keep.push_back(i);
  } else {
    const double scale = columns / (x_hi - x_lo);
    std::size_t i = begin;
    while (i < end) {
      const long col = static_cast<long>(std::floor((x[i] - x_lo) * scale));
      std::size_t first = i, last = i, lo = i, hi = i;
      for (; i < end && static_cast<long>(std::floor((x[i] - x_lo) * scale)) == col; ++i) {
        last = i;
        if (y[i] < y[lo]) lo = i;
        if (y[i] > y[hi]) hi = i;
      }
      std::size_t picks[4] = {first, std::min(lo, hi), std::max(lo, hi), last};
      for (std::size_t p : picks)
        if (keep.empty() || keep.back() < p) keep.push_back(p);
    }
  }
  if (end < n) keep.push_back(end);
  return keep;
}

std::string tick_label(double v, double step) {
  int decimals = 0;
  if (step > 0) decimals = std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
  if (step > 0 && std::abs(step * std::pow(10.0, decimals) - std::round(step * std::pow(10.0, decimals))) > 1e-6) ++decimals;
  if (step > 0 && std::abs(v) < 1e-6 * step) v = 0;
  std::string out = fmt::format("{:.{}f}", v, std::min(decimals, 9));
  if (out.find_first_not_of("-0.") == std::string::npos && out[0] == '-') out.erase(0, 1);
  return out;
}

std::vector<double> axis_ticks(double lo, double hi, int max_ticks) {
  std::vector<double> t = nice_ticks(lo, hi, std::max(2, max_ticks));
  for (int n = max_ticks + 1; t.size() < 4 && n <= 24; ++n) t = nice_ticks(lo, hi, n);
  return t;
}

namespace {

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  void settle(std::optional<double> fixed_lo, std::optional<double> fixed_hi, double pad_fraction) {
    if (lo > hi) lo = hi = 0;
    if (hi - lo < 1e-12) {
      const double half = std::max(std::abs(lo) * 0.05, 1e-3);
      lo -= half;
      hi += half;
    } else {
      const double pad = (hi - lo) * pad_fraction;
      lo -= pad;
      hi += pad;
    }
    if (fixed_lo) lo = *fixed_lo;
    if (fixed_hi) hi = *fixed_hi;
    if (!(hi > lo)) hi = lo + 1;
  }
};

Range x_range(const Plot& p) {
  Range xr;
  for (const Series& s : p.series)
    for (double v : s.x) xr.add(v);
  for (const VLine& v : p.vlines) xr.add(v.x);
  xr.settle(p.x.min, p.x.max, 0.0);
  return xr;
}

Range y_range(const Plot& p, const Range& xr) {
  Range yr;
  for (const Series& s : p.series) {
    const std::size_t n = std::min(s.x.size(), s.y.size());
    for (std::size_t i = 0; i < n; ++i)
      if (s.x[i] >= xr.lo && s.x[i] <= xr.hi) yr.add(s.y[i]);
  }
  for (const HLine& l : p.hlines)
    if (l.autoscale) yr.add(l.y);
  for (const Band& b : p.bands) {
    if (b.y_lo) yr.add(*b.y_lo);
    if (b.y_hi) yr.add(*b.y_hi);
  }
  yr.settle(p.y.min, p.y.max, 0.06);
  return yr;
}

std::string axis_title(const Axis& a) { return a.unit.empty() ? a.label : fmt::format("{} [{}]", a.label, a.unit); }

// Everything of one plot in SVG user units: the ranges, the plot area, the
// title's lines and the legend's rows, all inside the viewBox (issue 29: no
// clipped text at any page width, since the SVG only scales).
struct Frame {
  Range xr, yr;
  double w = 0, h = 0, left = 74, right = 26, top = 0, bottom = 44, pw = 0, ph = 0;
  std::vector<std::string> title_lines;
  struct Item {
    std::string label, color;
    bool area = false, dashed = false, dot = false;
    double x = 0, y = 0;
  };
  std::vector<Item> legend;
  double px(double x) const { return left + (x - xr.lo) / (xr.hi - xr.lo) * pw; }
  double py(double y) const { return top + (yr.hi - y) / (yr.hi - yr.lo) * ph; }
  double cx(double x) const { return std::clamp(px(x), left, left + pw); }
  double cy(double y) const { return std::clamp(py(y), top, top + ph); }
};

constexpr double kTitlePx = 14, kTextPx = 12, kLineGap = 4;

// Words of `text` in lines no wider than `width` (a single long word stays whole).
std::vector<std::string> wrap(const std::string& text, double width, double font_px, bool bold) {
  std::vector<std::string> lines;
  std::string line, word;
  auto flush_word = [&] {
    if (word.empty()) return;
    const std::string joined = line.empty() ? word : line + " " + word;
    if (!line.empty() && text_width(joined, font_px, bold) > width) {
      lines.push_back(line);
      line = word;
    } else {
      line = joined;
    }
    word.clear();
  };
  for (char c : text) {
    if (c == ' ') flush_word();
    else word.push_back(c);
  }
  flush_word();
  if (!line.empty()) lines.push_back(line);
  return lines;
}

Frame frame(const Plot& p) {
  Frame f;
  f.w = p.width_px;
  f.h = p.height_px;
  f.xr = x_range(p);
  f.yr = y_range(p, f.xr);
  f.title_lines = wrap(p.title, f.w - 16, kTitlePx, true);
  double y = 4 + (kTitlePx + kLineGap) * static_cast<double>(f.title_lines.size());
  // Legend rows above the plot area, wrapped at the SVG's width (issue 29:
  // never on the data, never cut at the right edge).
  double x = f.left, row_y = y + kTextPx + 4;
  auto add = [&](const std::string& label, const std::string& color, bool area, bool dashed, bool dot = false) {
    if (label.empty()) return;
    const double item_w = 24 + text_width(label, kTextPx, false) + 14;
    if (x > f.left && x + item_w > f.w - 4) {
      x = f.left;
      row_y += kTextPx + 5;
    }
    f.legend.push_back({label, color, area, dashed, dot, x, row_y});
    x += item_w;
  };
  for (const Series& s : p.series) add(s.label, s.color, false, s.dashed, s.markers);
  for (const HLine& l : p.hlines) add(l.label, l.color, false, l.dashed);
  for (const Band& b : p.bands) add(b.label, b.color, true, false);
  f.top = (f.legend.empty() ? y : row_y) + 12;
  f.h = std::max(f.h, f.top + f.bottom + 120); // a tall header does not squash the data
  f.pw = f.w - f.left - f.right;
  f.ph = f.h - f.top - f.bottom;
  return f;
}

void draw_axes(std::string& o, const Plot& p, const Frame& f) {
  o += fmt::format(R"(<rect x="{:.1f}" y="{:.1f}" width="{:.1f}" height="{:.1f}" fill="#fcfcfc" stroke="#999"/>)", f.left, f.top, f.pw, f.ph);
  o += '\n';
  const auto xt = axis_ticks(f.xr.lo, f.xr.hi, std::max(5, static_cast<int>(f.pw / 90)));
  const auto yt = axis_ticks(f.yr.lo, f.yr.hi, std::max(5, static_cast<int>(f.ph / 40)));
  const double xstep = xt.size() > 1 ? xt[1] - xt[0] : 0, ystep = yt.size() > 1 ? yt[1] - yt[0] : 0;
  for (double t : xt) {
    // A label at the right edge ends there rather than running past it; one
    // at the left edge starts at the axis, clear of the lowest y label.
    const std::string label = tick_label(t, xstep);
    const double x = f.px(t), half = text_width(label, kTextPx, false) / 2;
    const bool at_right = x + half > f.w - 2, at_left = x - half < f.left - 2;
    const char* anchor = at_right ? "end" : at_left ? "start" : "middle";
    o += fmt::format(R"(<line x1="{0:.1f}" y1="{1:.1f}" x2="{0:.1f}" y2="{2:.1f}" stroke="#e4e4e4"/><text class="tick" x="{3:.1f}" y="{4:.1f}" text-anchor="{5}">{6}</text>)",
                     x, f.top, f.top + f.ph, at_right ? f.w - 2 : x, f.top + f.ph + 15, anchor, label);
    o += '\n';
  }
  for (double t : yt) {
    o += fmt::format(R"(<line x1="{0:.1f}" y1="{1:.1f}" x2="{2:.1f}" y2="{1:.1f}" stroke="#e4e4e4"/><text class="tick" x="{3:.1f}" y="{4:.1f}" text-anchor="end">{5}</text>)",
                     f.left, f.py(t), f.left + f.pw, f.left - 5, f.py(t) + 4, tick_label(t, ystep));
    o += '\n';
  }
  o += fmt::format(R"(<text x="{:.1f}" y="{:.1f}" text-anchor="middle">{}</text>)", f.left + f.pw / 2, f.h - 8, xml_escape(axis_title(p.x)));
  o += fmt::format(R"~(<text transform="translate(14 {:.1f}) rotate(-90)" text-anchor="middle">{}</text>)~", f.top + f.ph / 2,
                   xml_escape(axis_title(p.y)));
  o += '\n';
}

void draw_limits(std::string& o, const Plot& p, const Frame& f) {
  for (const Band& b : p.bands) {
    const double x0 = b.x_lo ? f.cx(*b.x_lo) : f.left, x1 = b.x_hi ? f.cx(*b.x_hi) : f.left + f.pw;
    const double y0 = b.y_hi ? f.cy(*b.y_hi) : f.top, y1 = b.y_lo ? f.cy(*b.y_lo) : f.top + f.ph;
    o += fmt::format(R"(<rect class="band" x="{:.1f}" y="{:.1f}" width="{:.1f}" height="{:.1f}" fill="{}" fill-opacity="{:.2f}"/>)", x0, y0,
                     std::max(0.0, x1 - x0), std::max(0.0, y1 - y0), xml_escape(b.color), b.opacity);
    o += '\n';
  }
  double offscale_top = f.top + 12, offscale_bottom = f.top + f.ph - 5;
  for (const HLine& l : p.hlines) {
    if (l.y > f.yr.hi || l.y < f.yr.lo) {
      // Off scale: an arrow at the edge it lies beyond, with its value.
      const bool above = l.y > f.yr.hi;
      if (!l.label.empty() || !above) {
        double& y = above ? offscale_top : offscale_bottom;
        o += fmt::format(R"(<text class="offscale" x="{:.1f}" y="{:.1f}" text-anchor="end" fill="{}">{} {} ({:g}, off scale)</text>)",
                         f.left + f.pw - 4, y, xml_escape(l.color), above ? "&#9650;" : "&#9660;",
                         xml_escape(l.label.empty() ? std::string("limit") : l.label), l.y);
        y += above ? 13 : -13;
        o += '\n';
      }
      continue;
    }
    o += fmt::format(R"(<line class="limit" x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}" stroke="{}" stroke-width="1.2"{}/>)", f.left,
                     f.py(l.y), f.left + f.pw, f.py(l.y), xml_escape(l.color), l.dashed ? R"( stroke-dasharray="6 4")" : "");
    o += '\n';
  }
}

void draw_series(std::string& o, const Plot& p, const Frame& f) {
  for (const Series& s : p.series) {
    if (s.markers) {
      // Unordered points: at most ~3000 dots, evenly strided, as one path
      // of zero-length strokes with round caps (a dot each): one element
      // for the browser to parse and lay out, not one per point (611 in the
      // studio's answer, issue 37).
      const std::size_t n = std::min(s.x.size(), s.y.size()), stride = std::max<std::size_t>(1, n / 3000);
      std::string dots;
      for (std::size_t i = 0; i < n; i += stride) {
        if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i]) || s.x[i] < f.xr.lo || s.x[i] > f.xr.hi) continue;
        dots += fmt::format("M{:.1f} {:.1f}h0", f.px(s.x[i]), f.py(s.y[i]));
      }
      if (!dots.empty()) {
        o += fmt::format(R"(<path class="series" fill="none" stroke="{}" stroke-opacity="0.6" stroke-width="{:.1f}" )"
                         R"(stroke-linecap="round" d="{}"/>)",
                         xml_escape(s.color), 2 * std::max(1.8, s.width_px / 2), dots);
        o += '\n';
      }
      continue;
    }
    const auto keep = decimate_min_max(s.x, s.y, f.xr.lo, f.xr.hi, static_cast<int>(f.pw));
    std::string points;
    points.reserve(keep.size() * 14);
    for (std::size_t i : keep) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      points += fmt::format("{:.1f},{:.1f} ", f.px(s.x[i]), f.py(s.y[i]));
    }
    if (!points.empty()) points.pop_back();
    o += fmt::format(R"(<polyline class="series" fill="none" stroke="{}" stroke-width="{:.1f}"{} points="{}"/>)", xml_escape(s.color),
                     s.width_px, s.dashed ? R"( stroke-dasharray="7 4")" : "", points);
    o += '\n';
  }
}

// Marker lines with their labels at the top of the plot area: a label that
// would run past the right edge is set to the left of its line, and labels
// that would overlap step down a row.
void draw_markers(std::string& o, const Plot& p, const Frame& f) {
  std::vector<std::vector<std::pair<double, double>>> rows;
  for (const VLine& v : p.vlines) {
    const double x = f.cx(v.x);
    o += fmt::format(R"(<line class="marker" x1="{0:.1f}" y1="{1:.1f}" x2="{0:.1f}" y2="{2:.1f}" stroke="{3}" stroke-dasharray="3 3"/>)", x,
                     f.top, f.top + f.ph, xml_escape(v.color));
    if (!v.label.empty()) {
      const double tw = text_width(v.label, kTextPx, false);
      const bool left_of = x + 3 + tw > f.left + f.pw - 2;
      const double x0 = left_of ? x - 3 - tw : x + 3;
      std::size_t row = 0;
      for (; row < rows.size(); ++row) {
        bool clash = false;
        for (const auto& [a, b] : rows[row]) clash = clash || (x0 < b + 4 && x0 + tw > a - 4);
        if (!clash) break;
      }
      if (row == rows.size()) rows.emplace_back();
      rows[row].push_back({x0, x0 + tw});
      o += fmt::format(R"(<text class="marker-label" x="{:.1f}" y="{:.1f}" fill="{}">{}</text>)", x0, f.top + 12 + 13 * static_cast<double>(row),
                       xml_escape(v.color), xml_escape(v.label));
    }
    o += '\n';
  }
}

void draw_legend(std::string& o, const Frame& f) {
  for (const Frame::Item& it : f.legend) {
    if (it.area) {
      o += fmt::format(R"(<rect x="{:.1f}" y="{:.1f}" width="18" height="9" fill="{}" fill-opacity="0.35"/>)", it.x, it.y - 8, xml_escape(it.color));
    } else if (it.dot) { // operating points: dots, as drawn
      o += fmt::format(R"(<circle cx="{:.1f}" cy="{:.1f}" r="3.5" fill="{}"/>)", it.x + 9, it.y - 4, xml_escape(it.color));
    } else {
      o += fmt::format(R"(<line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}" stroke="{}" stroke-width="2"{}/>)", it.x, it.y - 4, it.x + 18,
                       it.y - 4, xml_escape(it.color), it.dashed ? R"( stroke-dasharray="5 2")" : "");
    }
    o += fmt::format(R"(<text class="legend" x="{:.1f}" y="{:.1f}">{}</text>)", it.x + 24, it.y, xml_escape(it.label));
    o += '\n';
  }
}

} // namespace

double text_width(std::string_view text, double font_px, bool bold) {
  // Code points (UTF-8 continuation bytes do not count) times a generous
  // average advance of sans-serif digits and letters.
  std::size_t n = 0;
  for (unsigned char c : text) n += (c & 0xC0) != 0x80 ? 1 : 0;
  return static_cast<double>(n) * font_px * (bold ? 0.64 : 0.6);
}

std::pair<double, double> x_extent(const Plot& p) {
  const Range r = x_range(p);
  return {r.lo, r.hi};
}

std::pair<double, double> y_extent(const Plot& p) {
  const Range r = y_range(p, x_range(p));
  return {r.lo, r.hi};
}

std::string to_svg(const Plot& p) {
  const Frame f = frame(p);
  std::string o = fmt::format(R"(<svg xmlns="http://www.w3.org/2000/svg" class="plot" id="svg-{0}" viewBox="0 0 {1} {2}" width="100%" )"
                              R"(font-family="sans-serif" font-size="{3}"><title>{4}</title>)",
                              xml_escape(p.id), f.w, f.h, kTextPx, xml_escape(p.title));
  o += '\n';
  const std::string clip = xml_escape(p.id) + "-clip";
  o += fmt::format(R"(<defs><clipPath id="{}"><rect x="{:.1f}" y="{:.1f}" width="{:.1f}" height="{:.1f}"/></clipPath></defs>)", clip,
                   f.left, f.top, f.pw, f.ph);
  o += '\n';
  for (std::size_t k = 0; k < f.title_lines.size(); ++k) {
    o += fmt::format(R"(<text class="title" x="8" y="{:.1f}" font-size="{}" font-weight="bold">{}</text>)",
                     4 + kTitlePx + (kTitlePx + kLineGap) * static_cast<double>(k), kTitlePx, xml_escape(f.title_lines[k]));
    o += '\n';
  }
  draw_axes(o, p, f);
  o += fmt::format(R"~(<g class="data" clip-path="url(#{})">)~", clip);
  o += '\n';
  draw_limits(o, p, f);
  draw_series(o, p, f);
  o += "</g>\n";
  draw_markers(o, p, f);
  draw_legend(o, f);
  o += "</svg>\n";
  return o;
}

} // namespace sreh::svg
