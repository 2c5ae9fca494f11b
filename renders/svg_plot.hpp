// Dependency-free SVG line plots (issue 7, 29; design/mujoco.md "Plots": no C++
// plotting library is packaged in Debian 12). Axes with "nice" ticks, units,
// a legend, horizontal limit lines, vertical markers and shaded bands.
// Long series are decimated to min/max per pixel column, so a plot stays a
// few tens of kB whatever the trace length, and spikes survive.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/html_page.hpp"

namespace sreh::svg {

struct Series {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;
  std::string color = "#1f77b4";
  double width_px = 1.5;
  bool dashed = false;
  bool markers = false; // dots instead of a line (operating points)
};

struct HLine {
  double y = 0;
  std::string label; // empty: not in the legend
  std::string color = "#d62728";
  bool dashed = true;
  // false: a limit that does not stretch the axis; when it lies outside the
  // data's range an arrow at the edge names it ("off scale").
  bool autoscale = true;
};

struct VLine {
  double x = 0;
  std::string label; // written next to the line, at the top
  std::string color = "#555555";
};

// A shaded rectangle; an unset edge extends to the plot area's edge.
struct Band {
  std::optional<double> x_lo, x_hi, y_lo, y_hi;
  std::string label;
  std::string color = "#2ca02c";
  double opacity = 0.15;
};

struct Axis {
  std::string label;
  std::string unit;
  std::optional<double> min, max; // unset: from the data
};

struct Plot {
  std::string id = "plot"; // unique within one HTML page (clip path id)
  std::string title;
  Axis x, y;
  std::vector<Series> series;
  std::vector<HLine> hlines;
  std::vector<VLine> vlines;
  std::vector<Band> bands;
  // The viewBox in user units; on a page the SVG takes the full width and
  // scales (issue 29), so these set the proportions and the text's size
  // relative to the plot. The height grows when the title and legend need it.
  int width_px = 900;
  int height_px = 300;
};

// The SVG element (no XML prolog), ready to inline in HTML: the title
// wrapped to the width, the legend in rows above the plot area (never on the
// data), every text inside the viewBox.
std::string to_svg(const Plot& plot);

// The axis ranges to_svg draws (the interactive figure uses the same): x
// from the data and markers unless fixed; y from the data within that x
// range, the autoscaling limit lines and the bands, padded 6 %.
std::pair<double, double> x_extent(const Plot& plot);
std::pair<double, double> y_extent(const Plot& plot);

// A generous estimate of the width of `text` at `font_px` in a sans-serif
// font, for laying text out inside the viewBox.
double text_width(std::string_view text, double font_px, bool bold = false);

// Tick values of one axis as drawn: nice_ticks with at least 4 inside the
// range (issue 16: every plot readable without guessing).
std::vector<double> axis_ticks(double lo, double hi, int max_ticks);
// The label of a tick: enough decimals for `step`, ASCII minus, no "-0".
std::string tick_label(double v, double step);

// About `max_ticks` (>= 2) tick values at 1/2/2.5/5 x 10^n covering [lo, hi].
std::vector<double> nice_ticks(double lo, double hi, int max_ticks = 6);

// Indices of the points kept when `x` (ascending) is drawn into `columns`
// pixel columns over [x_lo, x_hi]: per column the first, min, max and last
// point, in order; plus one point either side of the range.
std::vector<std::size_t> decimate_min_max(const std::vector<double>& x, const std::vector<double>& y, double x_lo,
                                          double x_hi, int columns);

// One escaper for every page (io/html_page.hpp).
inline std::string xml_escape(std::string_view text) { return io::html_escape(text); }

} // namespace sreh::svg
