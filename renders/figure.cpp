#include "renders/figure.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "io/html_page.hpp"
#include "renders/report_assets.hpp" // generated from libjs-dygraphs (renders/CMakeLists.txt)

namespace sreh::report {

namespace {

constexpr const char* kHelperJs = R"js(
function srehPlot(id, s) {
  var el = document.getElementById(id);
  el.parentNode.classList.add('live'); // laid out before dygraphs measures it
  var series = {};
  var fmt = function (v) { return String(+v.toPrecision(6)); };
  s.dashed.forEach(function (d, i) { if (d) series[s.labels[i + 1]] = {strokePattern: [7, 4], strokeWidth: 2}; });
  // Title, legend and the key of the limit lines are HTML outside the chart
  // (issue 29): they wrap instead of colliding with the data or each other.
  new Dygraph(el, s.data, {
    labels: s.labels, colors: s.colors, xlabel: s.xlabel, ylabel: s.ylabel,
    labelsDiv: document.getElementById(id + '-legend'), legend: 'always', labelsSeparateLines: false,
    strokeWidth: 1.3, series: series, valueRange: s.yrange, dateWindow: s.xrange,
    axes: {x: {axisLabelFormatter: fmt, valueFormatter: fmt}, y: {axisLabelWidth: 70, axisLabelFormatter: fmt, valueFormatter: fmt}},
    underlayCallback: function (ctx, area, g) {
      s.bands.forEach(function (b) {
        var x0 = b[0] === null ? area.x : g.toDomXCoord(b[0]), x1 = b[1] === null ? area.x + area.w : g.toDomXCoord(b[1]);
        var y0 = b[3] === null ? area.y : g.toDomYCoord(b[3]), y1 = b[2] === null ? area.y + area.h : g.toDomYCoord(b[2]);
        ctx.globalAlpha = b[5]; ctx.fillStyle = b[4]; ctx.fillRect(x0, y0, x1 - x0, y1 - y0); ctx.globalAlpha = 1;
      });
      s.hlines.forEach(function (h) {
        var y = g.toDomYCoord(h[0]); ctx.strokeStyle = h[1]; ctx.lineWidth = 1.2; ctx.setLineDash(h[2] ? [6, 4] : []);
        ctx.beginPath(); ctx.moveTo(area.x, y); ctx.lineTo(area.x + area.w, y); ctx.stroke(); ctx.setLineDash([]);
      });
    }
  });
}
)js";

// Shortest text that reads back as the same number; JSON null for non-finite.
std::string num(double v) { return std::isfinite(v) ? fmt::format("{}", v) : std::string("null"); }

std::string js_string(const std::string& s) {
  std::string o = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') o.push_back('\\');
    if (c == '<') {
      o.append("\\u003c"); // never close the <script>
      continue;
    }
    o.push_back(c);
  }
  o.push_back('"');
  return o;
}

std::string axis_title(const svg::Axis& a) { return a.unit.empty() ? a.label : fmt::format("{} [{}]", a.label, a.unit); }

std::string opt(const std::optional<double>& v) { return v ? num(*v) : std::string("null"); }

} // namespace

std::string interactive_head() {
  return fmt::format("<style>{}</style>\n<script>{}</script>\n<script>{}</script>\n", find_report_asset("dygraph.min.css"),
                     find_report_asset("dygraph.min.js"), kHelperJs);
}

std::string page_head() { return fmt::format("<style>{}</style>\n{}", io::kPageCss, interactive_head()); }

namespace {

// The dygraph's data: the min/max decimation of every series over ~1500
// columns, as JSON rows [x, y1, y2, ...]; labels made unique.
struct DyData {
  std::string labels, colors, dashed, rows;
};

DyData dy_data(const svg::Plot& p) {
  const std::vector<double>& x = p.series.front().x;
  const auto [lo, hi] = svg::x_extent(p);
  std::set<std::size_t> keep;
  for (const svg::Series& s : p.series) {
    for (std::size_t i : svg::decimate_min_max(x, s.y, lo, hi, 1500)) keep.insert(i);
  }
  DyData d;
  d.labels = js_string(axis_title(p.x));
  std::set<std::string> seen;
  for (std::size_t k = 0; k < p.series.size(); ++k) {
    // An unlabelled series is the other side of the one before (e.g. -limit).
    std::string label = !p.series[k].label.empty() ? p.series[k].label
                        : k > 0 && !p.series[k - 1].label.empty() ? p.series[k - 1].label + " (-)"
                                                                 : fmt::format("({})", k + 1);
    while (!seen.insert(label).second) label.push_back('\'');
    d.labels.append(",").append(js_string(label));
    if (k) d.colors.append(","), d.dashed.append(",");
    d.colors.append(js_string(p.series[k].color));
    d.dashed.append(p.series[k].dashed ? "true" : "false");
  }
  for (std::size_t i : keep) {
    if (!d.rows.empty()) d.rows += ',';
    d.rows.append("[").append(num(x[i]));
    for (const svg::Series& s : p.series) d.rows.append(",").append(num(s.y[i]));
    d.rows.append("]");
  }
  return d;
}

// The key of the limit lines and bands under the dygraph's legend: every
// line on the chart named (issue 29).
std::string dy_key(const svg::Plot& p) {
  std::string key;
  const auto [lo, hi] = svg::y_extent(p);
  for (const svg::HLine& h : p.hlines) {
    if (h.label.empty()) continue;
    // A limit outside the drawn range (it does not stretch the axis) is named with its value, as on the SVG.
    const std::string off = h.y > hi ? fmt::format(" (&#9650; {:g}, off scale)", h.y) : h.y < lo ? fmt::format(" (&#9660; {:g}, off scale)", h.y) : "";
    key += fmt::format("<span class=\"k\"><i style=\"border-top:2px {} {}\"></i>{}{}</span>", h.dashed ? "dashed" : "solid",
                       svg::xml_escape(h.color), svg::xml_escape(h.label), off);
  }
  for (const svg::Band& b : p.bands) {
    if (b.label.empty()) continue;
    key += fmt::format("<span class=\"k\"><i style=\"height:9px;background:{};opacity:0.4\"></i>{}</span>",
                       svg::xml_escape(b.color), svg::xml_escape(b.label));
  }
  return key;
}

std::string dy_script(const svg::Plot& p, const std::string& id) {
  const DyData d = dy_data(p);
  std::string hlines, bands;
  for (const svg::HLine& h : p.hlines) {
    if (!hlines.empty()) hlines.append(",");
    hlines.append(fmt::format("[{},{},{}]", num(h.y), js_string(h.color), h.dashed ? "true" : "false"));
  }
  for (const svg::Band& b : p.bands) {
    if (!bands.empty()) bands.append(",");
    bands.append(fmt::format("[{},{},{},{},{},{}]", opt(b.x_lo), opt(b.x_hi), opt(b.y_lo), opt(b.y_hi), js_string(b.color), num(b.opacity)));
  }
  const auto [x_lo, x_hi] = svg::x_extent(p);
  const auto [y_lo, y_hi] = svg::y_extent(p); // the SVG's range: limit lines stay on the chart
  return fmt::format("<script>srehPlot(\"{}\",{{xlabel:{},ylabel:{},labels:[{}],colors:[{}],dashed:[{}],"
                     "xrange:[{},{}],yrange:[{},{}],hlines:[{}],bands:[{}],data:[{}]}});</script>\n",
                     id, js_string(axis_title(p.x)), js_string(axis_title(p.y)), d.labels, d.colors, d.dashed, num(x_lo), num(x_hi),
                     num(y_lo), num(y_hi), hlines, bands, d.rows);
}

} // namespace

std::string figure(const svg::Plot& p, bool interactive) {
  bool shared_x = interactive && !p.series.empty();
  for (const svg::Series& s : p.series) {
    shared_x = shared_x && !s.markers && s.x == p.series.front().x && s.y.size() == s.x.size();
  }
  std::string o = fmt::format("<div class=\"fig\" id=\"fig-{}\">\n", svg::xml_escape(p.id));
  const std::string id = "dy-" + svg::xml_escape(p.id);
  if (shared_x) {
    o += fmt::format("<div class=\"dytitle\">{}</div><div class=\"dylegend\" id=\"{}-legend\"></div><div class=\"dykey\">{}</div>\n",
                     svg::xml_escape(p.title), id, dy_key(p));
    o += fmt::format("<div class=\"dy\" id=\"{}\"></div><div class=\"hint\">drag to zoom, shift-drag to pan, double-click to reset</div>\n", id);
  }
  o += "<div class=\"static\">" + svg::to_svg(p) + "</div>\n";
  if (shared_x) o += dy_script(p, id);
  return o + "</div>\n";
}

} // namespace sreh::report
