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

std::string axis_title(const Axis& a) { return a.unit.empty() ? a.label : fmt::format("{} [{}]", a.label, a.unit); }

} // namespace

std::string to_svg(const Plot& p) {
  const double left = 70, right = 18, top = 46, bottom = 44;
  const double w = p.width_px, h = p.height_px;
  const double pw = w - left - right, ph = h - top - bottom;

  Range xr, yr;
  for (const Series& s : p.series)
    for (double v : s.x) xr.add(v);
  for (const VLine& v : p.vlines) xr.add(v.x);
  xr.settle(p.x.min, p.x.max, 0.0);
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

  auto px = [&](double x) { return left + (x - xr.lo) / (xr.hi - xr.lo) * pw; };
  auto py = [&](double y) { return top + (yr.hi - y) / (yr.hi - yr.lo) * ph; };
  auto cx = [&](double x) { return std::clamp(px(x), left, left + pw); };
  auto cy = [&](double y) { return std::clamp(py(y), top, top + ph); };

  std::string o;
  o += fmt::format(R"(<svg xmlns="http://www.w3.org/2000/svg" class="plot" width="{}" height="{}" viewBox="0 0 {} {}" font-family="sans-serif" font-size="11">)",
                   p.width_px, p.height_px, p.width_px, p.height_px);
  o += '\n';
  const std::string clip = xml_escape(p.id) + "-clip";
  o += fmt::format(R"(<defs><clipPath id="{}"><rect x="{:.1f}" y="{:.1f}" width="{:.1f}" height="{:.1f}"/></clipPath></defs>)", clip,
                   left, top, pw, ph);
  o += '\n';
  o += fmt::format(R"(<text x="{:.1f}" y="15" font-size="13" font-weight="bold">{}</text>)", left, xml_escape(p.title));
  o += '\n';
  o += fmt::format(R"(<rect x="{:.1f}" y="{:.1f}" width="{:.1f}" height="{:.1f}" fill="#fcfcfc" stroke="#999"/>)", left, top, pw, ph);
  o += '\n';

  // Grid and ticks.
  const auto xt = axis_ticks(xr.lo, xr.hi, std::max(5, static_cast<int>(pw / 90)));
  const auto yt = axis_ticks(yr.lo, yr.hi, std::max(5, static_cast<int>(ph / 40)));
  const double xstep = xt.size() > 1 ? xt[1] - xt[0] : 0, ystep = yt.size() > 1 ? yt[1] - yt[0] : 0;
  for (double t : xt) {
    o += fmt::format(R"(<line x1="{0:.1f}" y1="{1:.1f}" x2="{0:.1f}" y2="{2:.1f}" stroke="#e4e4e4"/><text x="{0:.1f}" y="{3:.1f}" text-anchor="middle">{4}</text>)",
                     px(t), top, top + ph, top + ph + 14, tick_label(t, xstep));
    o += '\n';
  }
  for (double t : yt) {
    o += fmt::format(R"(<line x1="{0:.1f}" y1="{1:.1f}" x2="{2:.1f}" y2="{1:.1f}" stroke="#e4e4e4"/><text x="{3:.1f}" y="{4:.1f}" text-anchor="end">{5}</text>)",
                     left, py(t), left + pw, left - 5, py(t) + 4, tick_label(t, ystep));
    o += '\n';
  }
  o += fmt::format(R"(<text x="{:.1f}" y="{:.1f}" text-anchor="middle">{}</text>)", left + pw / 2, h - 8, xml_escape(axis_title(p.x)));
  o += fmt::format(R"~(<text transform="translate(14 {:.1f}) rotate(-90)" text-anchor="middle">{}</text>)~", top + ph / 2,
                   xml_escape(axis_title(p.y)));
  o += '\n';

  o += fmt::format(R"~(<g clip-path="url(#{})">)~", clip);
  o += '\n';
  for (const Band& b : p.bands) {
    const double x0 = b.x_lo ? cx(*b.x_lo) : left, x1 = b.x_hi ? cx(*b.x_hi) : left + pw;
    const double y0 = b.y_hi ? cy(*b.y_hi) : top, y1 = b.y_lo ? cy(*b.y_lo) : top + ph;
    o += fmt::format(R"(<rect class="band" x="{:.1f}" y="{:.1f}" width="{:.1f}" height="{:.1f}" fill="{}" fill-opacity="{:.2f}"/>)", x0, y0,
                     std::max(0.0, x1 - x0), std::max(0.0, y1 - y0), xml_escape(b.color), b.opacity);
    o += '\n';
  }
  for (const HLine& l : p.hlines) {
    if (l.y > yr.hi || l.y < yr.lo) {
      // Off scale: an arrow at the edge it lies beyond, with its value.
      const bool above = l.y > yr.hi;
      if (!l.label.empty() || !above) {
        o += fmt::format(R"(<text class="offscale" x="{:.1f}" y="{:.1f}" text-anchor="end" fill="{}">{} {} ({:g}, off scale)</text>)",
                         left + pw - 4, above ? top + 12 : top + ph - 5, xml_escape(l.color), above ? "&#9650;" : "&#9660;",
                         xml_escape(l.label.empty() ? std::string("limit") : l.label), l.y);
        o += '\n';
      }
      continue;
    }
    o += fmt::format(R"(<line class="limit" x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}" stroke="{}" stroke-width="1.2"{}/>)", left, py(l.y),
                     left + pw, py(l.y), xml_escape(l.color), l.dashed ? R"( stroke-dasharray="6 4")" : "");
    o += '\n';
  }
  for (const Series& s : p.series) {
    if (s.markers) {
      // Unordered points: at most ~3000 dots, evenly strided.
      const std::size_t n = std::min(s.x.size(), s.y.size()), stride = std::max<std::size_t>(1, n / 3000);
      o += fmt::format(R"(<g class="series" fill="{}" fill-opacity="0.6">)", xml_escape(s.color));
      for (std::size_t i = 0; i < n; i += stride) {
        if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i]) || s.x[i] < xr.lo || s.x[i] > xr.hi) continue;
        o += fmt::format(R"(<circle cx="{:.1f}" cy="{:.1f}" r="1.8"/>)", px(s.x[i]), py(s.y[i]));
      }
      o += "</g>\n";
      continue;
    }
    const auto keep = decimate_min_max(s.x, s.y, xr.lo, xr.hi, static_cast<int>(pw));
    std::string points;
    points.reserve(keep.size() * 14);
    for (std::size_t i : keep) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      points += fmt::format("{:.1f},{:.1f} ", px(s.x[i]), py(s.y[i]));
    }
    if (!points.empty()) points.pop_back();
    o += fmt::format(R"(<polyline class="series" fill="none" stroke="{}" stroke-width="{:.1f}"{} points="{}"/>)", xml_escape(s.color), s.width_px,
                     s.dashed ? R"( stroke-dasharray="5 3")" : "", points);
    o += '\n';
  }
  for (const VLine& v : p.vlines) {
    o += fmt::format(R"(<line class="marker" x1="{0:.1f}" y1="{1:.1f}" x2="{0:.1f}" y2="{2:.1f}" stroke="{3}" stroke-dasharray="3 3"/>)",
                     px(v.x), top, top + ph, xml_escape(v.color));
    if (!v.label.empty()) {
      o += fmt::format(R"(<text x="{:.1f}" y="{:.1f}" fill="{}">{}</text>)", px(v.x) + 3, top + 12, xml_escape(v.color), xml_escape(v.label));
    }
    o += '\n';
  }
  o += "</g>\n";

  // Legend: one row above the plot area.
  double lx = left;
  const double ly = 32;
  auto legend_item = [&](const std::string& label, const std::string& color, bool area, bool dashed) {
    if (label.empty()) return;
    if (area) {
      o += fmt::format(R"(<rect x="{:.1f}" y="{:.1f}" width="16" height="9" fill="{}" fill-opacity="0.35"/>)", lx, ly - 8, xml_escape(color));
    } else {
      o += fmt::format(R"(<line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}" stroke="{}" stroke-width="2"{}/>)", lx, ly - 4, lx + 16, ly - 4,
                       xml_escape(color), dashed ? R"( stroke-dasharray="4 2")" : "");
    }
    o += fmt::format(R"(<text x="{:.1f}" y="{:.1f}">{}</text>)", lx + 20, ly, xml_escape(label));
    lx += 28 + 6.0 * static_cast<double>(label.size());
  };
  for (const Series& s : p.series) legend_item(s.label, s.color, false, s.dashed);
  for (const HLine& l : p.hlines) legend_item(l.label, l.color, false, l.dashed);
  for (const Band& b : p.bands) legend_item(b.label, b.color, true, false);
  o += "\n</svg>\n";
  return o;
}

} // namespace sreh::svg
