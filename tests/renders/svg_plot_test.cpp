// SVG plots (issue 7): nice ticks, min/max decimation keeps spikes and bounds
// the size, markup is escaped.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include <cmath>

#include <fmt/format.h>

#include "renders/svg_plot.hpp"

namespace sreh::svg {
namespace {

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

TEST(NiceTicks, CoverTheRangeWithRoundSteps) {
  EXPECT_EQ(nice_ticks(0.0, 1.0, 6), (std::vector<double>{0.0, 0.2, 0.4, 0.6, 0.8, 1.0}));
  const auto t = nice_ticks(-0.013, 0.047, 5);
  ASSERT_GE(t.size(), 3u);
  EXPECT_NEAR(t[1] - t[0], 0.02, 1e-12);
  EXPECT_GE(t.front(), -0.013);
  EXPECT_LE(t.back(), 0.047);
  EXPECT_TRUE(nice_ticks(1.0, 1.0).empty());
}

// Issue 16: at least 4 labelled ticks per axis whatever the range, labels
// with the decimals the step needs, never "-0".
TEST(AxisTicks, AtLeastFourReadableLabelsOnAnyRange) {
  for (auto [lo, hi] : {std::pair{-0.00115, 0.00115}, std::pair{0.195, 0.2}, std::pair{0.0, 1.0}, std::pair{89.99, 90.01},
                        std::pair{-3000.0, 3000.0}, std::pair{24.0, 24.000001}}) {
    const auto t = axis_ticks(lo, hi, 5);
    ASSERT_GE(t.size(), 4u) << lo << " .. " << hi;
    std::set<std::string> labels;
    for (double v : t) labels.insert(tick_label(v, t[1] - t[0]));
    EXPECT_EQ(labels.size(), t.size()) << lo << " .. " << hi; // distinct
  }
  EXPECT_EQ(tick_label(-1e-18, 0.0005), "0.0000");
  EXPECT_EQ(tick_label(-0.001, 0.0005), "-0.0010");
  EXPECT_EQ(tick_label(2.5, 0.5), "2.5");
}

// A limit far outside the data does not flatten it; it is named at the edge.
TEST(SvgPlot, OffScaleLimitIsNamedNotScaledTo) {
  Plot p;
  p.series = {{"err", {0, 1, 2}, {0.001, -0.001, 0.0005}}};
  p.hlines = {{1.0, "tracking limit", "#d62728", true, false}, {-1.0, "", "#d62728", true, false}};
  const std::string s = to_svg(p);
  EXPECT_NE(s.find("tracking limit (1, off scale)"), std::string::npos);
  EXPECT_EQ(s.find("class=\"limit\""), std::string::npos);
  EXPECT_NE(s.find(">0.0010<"), std::string::npos);
}

// Issue 37: operating points are dots of one path (a round-capped
// zero-length stroke each), not an element per point: the studio's answer
// carried 611 circles, which the page parsed, laid out and painted on every
// answer. Every finite point in the x range is one dot.
TEST(SvgPlot, MarkersAreOnePathWithADotPerPoint) {
  Plot p;
  Series dots{"operating points", {}, {}};
  dots.markers = true;
  for (int i = 0; i < 611; ++i) {
    dots.x.push_back(i);
    dots.y.push_back(std::sin(0.1 * i));
  }
  dots.y[7] = std::nan("");
  p.series = {dots};
  const std::string s = to_svg(p);
  EXPECT_EQ(count(s, "<circle"), 1u); // the legend's swatch only
  EXPECT_EQ(count(s, "<path class=\"series\""), 1u);
  EXPECT_EQ(count(s, "h0"), 610u); // the NaN point left out
  EXPECT_NE(s.find("stroke-linecap=\"round\""), std::string::npos);
  // No point in range: no empty path.
  p.series[0].y.assign(611, std::nan(""));
  EXPECT_EQ(count(to_svg(p), "<path class=\"series\""), 0u);
}

TEST(Decimation, KeepsSpikesAndBoundsThePointCount) {
  std::vector<double> x(200000), y(200000);
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = static_cast<double>(i) * 1e-4;
    y[i] = std::sin(x[i]);
  }
  y[123457] = 50.0; // a one-sample spike must survive
  const auto keep = decimate_min_max(x, y, 0.0, x.back(), 700);
  EXPECT_LE(keep.size(), 4u * 700u + 2u);
  EXPECT_NE(std::find(keep.begin(), keep.end(), std::size_t{123457}), keep.end());
  EXPECT_TRUE(std::is_sorted(keep.begin(), keep.end()));
}

TEST(Decimation, ShortSeriesKeptWholeWithOneNeighbourOutside) {
  const std::vector<double> x{0, 1, 2, 3, 4}, y{0, 1, 0, 1, 0};
  EXPECT_EQ(decimate_min_max(x, y, 1.5, 3.5, 100), (std::vector<std::size_t>{1, 2, 3, 4}));
}

TEST(SvgPlot, HasAxesLegendLimitLinesBandsAndEscapedText) {
  Plot p;
  p.id = "t1";
  p.title = "a < b & c";
  p.x = {"time", "s", {}, {}};
  p.y = {"torque", "N m", {}, {}};
  p.series = {{"motor torque", {0, 1, 2}, {0, 0.3, -0.2}, "#f00", 1.5, false}};
  p.hlines = {{0.485, "motor limit", "#d62728", true}};
  p.bands = {{{}, {}, -0.1, 0.1, "window", "#0a0", 0.2}};
  p.vlines = {{1.0, "(b)", "#555"}};
  const std::string s = to_svg(p);
  EXPECT_EQ(s.rfind("<svg", 0), 0u);
  EXPECT_NE(s.find("a &lt; b &amp; c"), std::string::npos);
  EXPECT_NE(s.find("time [s]"), std::string::npos);
  EXPECT_NE(s.find("torque [N m]"), std::string::npos);
  EXPECT_EQ(count(s, "class=\"series\""), 1u);
  EXPECT_EQ(count(s, "class=\"limit\""), 1u);
  EXPECT_EQ(count(s, "class=\"band\""), 1u);
  EXPECT_NE(s.find(">motor limit<"), std::string::npos);
  EXPECT_NE(s.find(">(b)<"), std::string::npos);
  EXPECT_NE(s.find("clip-path=\"url(#t1-clip)\""), std::string::npos);
  EXPECT_GE(count(s, "<text"), 8u); // title, ticks, axis titles, legend
}

TEST(SvgPlot, ConstantAndEmptySeriesStillDraw) {
  Plot p;
  p.series = {{"flat", {0, 1}, {24, 24}, "#000", 1, false}, {"empty", {}, {}, "#000", 1, false}};
  const std::string s = to_svg(p);
  EXPECT_EQ(s.find("nan"), std::string::npos);
  EXPECT_EQ(s.find("inf"), std::string::npos);
  EXPECT_NE(s.find("</svg>"), std::string::npos);
}

// The numbers of every attribute `name`="..." of `tag` elements in `svg`.
std::vector<double> attr(const std::string& svg, const std::string& tag, const std::string& name) {
  std::vector<double> out;
  for (std::size_t a = svg.find("<" + tag + " "); a != std::string::npos; a = svg.find("<" + tag + " ", a + 1)) {
    const std::size_t end = svg.find('>', a), at = svg.find(" " + name + "=\"", a);
    if (at < end) out.push_back(std::stod(svg.substr(at + name.size() + 3)));
  }
  return out;
}

// Issue 29: the SVG scales to the page (viewBox, width 100 %); a title too
// long for one line wraps; a legend too long for one row wraps into rows
// above the plot area, never on the data; every text starts inside the width.
TEST(SvgPlot, TitleAndLegendWrapAboveThePlotAreaInsideTheViewBox) {
  Plot p;
  p.id = "wrap";
  p.title = "Module temperature under continuous cycling, from ambient (twin's thermal model, mean loss), "
            "with a title long enough to need a second line at any width";
  for (int k = 0; k < 9; ++k) p.series.push_back({"a series with a long legend label " + std::to_string(k), {0, 1}, {0, 1.0 * k}});
  const std::string s = to_svg(p);
  EXPECT_NE(s.find(fmt::format(R"(viewBox="0 0 {} )", p.width_px)), std::string::npos);
  EXPECT_NE(s.find(R"(width="100%")"), std::string::npos);
  EXPECT_GE(count(s, "class=\"title\""), 2u);
  const double plot_top = attr(s, "rect", "y").front(); // the clip rectangle: the plot area
  std::set<double> rows;
  for (std::size_t a = s.find("class=\"legend\""); a != std::string::npos; a = s.find("class=\"legend\"", a + 1)) {
    const double y = std::stod(s.substr(s.find("y=\"", a) + 3));
    const double x = std::stod(s.substr(s.find("x=\"", a) + 3));
    rows.insert(y);
    EXPECT_LT(y, plot_top) << "legend on the data";
    const std::size_t text = s.find('>', a) + 1;
    EXPECT_LE(x + text_width(s.substr(text, s.find('<', text) - text), 12), p.width_px) << "legend past the right edge";
  }
  EXPECT_GE(rows.size(), 3u);
  for (double x : attr(s, "text", "x")) EXPECT_GE(x, 0.0);
}

// A marker label at the right edge is set to the left of its line, and two
// labels at the same place step down instead of overlapping.
TEST(SvgPlot, MarkerLabelsStayInsideAndApart) {
  Plot p;
  p.series = {{"x", {0, 1}, {0, 1}}};
  p.vlines = {{1.0, "not completed"}, {0.5, "(b)"}, {0.501, "(f) complete"}};
  const std::string s = to_svg(p);
  std::vector<double> xs, ys;
  for (std::size_t a = s.find("class=\"marker-label\""); a != std::string::npos; a = s.find("class=\"marker-label\"", a + 1)) {
    xs.push_back(std::stod(s.substr(s.find("x=\"", a) + 3)));
    ys.push_back(std::stod(s.substr(s.find("y=\"", a) + 3)));
  }
  ASSERT_EQ(xs.size(), 3u);
  EXPECT_LE(xs[0] + text_width("not completed", 12), p.width_px - 26 + 1); // inside the plot area
  EXPECT_NE(ys[1], ys[2]);                                             // stepped down
}

} // namespace
} // namespace sreh::svg
