#include "renders/figure.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "renders/report_assets.hpp" // generated from libjs-dygraphs (renders/CMakeLists.txt)

namespace sreh::report {

const char* const kPageCss = R"css(
body{font-family:system-ui,-apple-system,"Segoe UI",sans-serif;margin:24px auto;max-width:1100px;color:#222;padding:0 16px}
h1{font-size:22px;margin-bottom:4px}h2{font-size:17px;margin-top:28px;border-bottom:1px solid #ddd;padding-bottom:4px}
.result{display:inline-block;padding:3px 12px;border-radius:4px;font-weight:bold;color:#fff}
.pass,.ok{background:#2e7d32}.fail,.bad{background:#c62828}
table{border-collapse:collapse;font-size:13px}td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}
th{background:#f2f2f2}td.l,th.l{text-align:left}td.okc{color:#2e7d32;font-weight:bold}td.badc{color:#c62828;font-weight:bold}
svg.plot{display:block;margin:10px 0;max-width:100%;height:auto}video,img.video{max-width:100%;background:#000}
pre,code.cmd{background:#f7f7f7;padding:6px 8px;font-size:13px;overflow-x:auto;display:block;white-space:pre-wrap}
.note{color:#666;font-size:12px}ul.failed li{color:#c62828;margin:3px 0}
.fig{margin:12px 0}.fig .dy{display:none;width:760px;max-width:100%;height:300px}
.fig.live .dy{display:block}.fig.live .static{display:none}
.fig .hint{display:none;color:#666;font-size:11px}.fig.live .hint{display:block}
@media print{.fig.live .dy,.fig.live .hint{display:none}.fig.live .static{display:block}video{display:none}}
)css";

namespace {

constexpr const char* kHelperJs = R"js(
function srehPlot(id, s) {
  var el = document.getElementById(id);
  el.parentNode.classList.add('live'); // laid out before dygraphs measures it
  var series = {};
  var fmt = function (v) { return String(+v.toPrecision(6)); };
  s.dashed.forEach(function (d, i) { if (d) series[s.labels[i + 1]] = {strokePattern: [6, 3]}; });
  new Dygraph(el, s.data, {
    labels: s.labels, colors: s.colors, title: s.title, xlabel: s.xlabel, ylabel: s.ylabel,
    legend: 'always', labelsSeparateLines: false, strokeWidth: 1.3, series: series,
    axes: {x: {axisLabelFormatter: fmt, valueFormatter: fmt}, y: {axisLabelWidth: 70, axisLabelFormatter: fmt, valueFormatter: fmt}},
    underlayCallback: function (ctx, area, g) {
      s.bands.forEach(function (b) {
        var x0 = b[0] === null ? area.x : g.toDomXCoord(b[0]), x1 = b[1] === null ? area.x + area.w : g.toDomXCoord(b[1]);
        var y0 = b[3] === null ? area.y : g.toDomYCoord(b[3]), y1 = b[2] === null ? area.y + area.h : g.toDomYCoord(b[2]);
        ctx.globalAlpha = b[5]; ctx.fillStyle = b[4]; ctx.fillRect(x0, y0, x1 - x0, y1 - y0); ctx.globalAlpha = 1;
      });
      s.hlines.forEach(function (h) {
        var y = g.toDomYCoord(h[0]); ctx.strokeStyle = h[1]; ctx.setLineDash([6, 4]);
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

std::string page_head() { return fmt::format("<style>{}</style>\n{}", kPageCss, interactive_head()); }

std::string figure(const svg::Plot& p, bool interactive) {
  bool shared_x = interactive && !p.series.empty();
  for (const svg::Series& s : p.series) {
    shared_x = shared_x && !s.markers && s.x == p.series.front().x && s.y.size() == s.x.size();
  }
  std::string o = fmt::format("<div class=\"fig\" id=\"fig-{}\">\n", svg::xml_escape(p.id));
  if (shared_x) {
    const std::string id = "dy-" + svg::xml_escape(p.id);
    o += fmt::format("<div class=\"dy\" id=\"{}\"></div><div class=\"hint\">drag to zoom, shift-drag to pan, double-click to reset</div>\n", id);
  }
  o += "<div class=\"static\">" + svg::to_svg(p) + "</div>\n";
  if (shared_x) {
    // Rows kept: the min/max decimation of every series over ~1500 columns.
    const std::vector<double>& x = p.series.front().x;
    const double lo = p.x.min.value_or(x.empty() ? 0.0 : x.front()), hi = p.x.max.value_or(x.empty() ? 1.0 : x.back());
    std::set<std::size_t> rows;
    for (const svg::Series& s : p.series) {
      for (std::size_t i : svg::decimate_min_max(x, s.y, lo, hi, 1500)) rows.insert(i);
    }
    std::string labels = js_string(axis_title(p.x)), colors, dashed, data;
    std::set<std::string> seen;
    for (std::size_t k = 0; k < p.series.size(); ++k) {
      // An unlabelled series is the other side of the one before (e.g. -limit).
      std::string label = !p.series[k].label.empty() ? p.series[k].label
                          : k > 0 && !p.series[k - 1].label.empty() ? p.series[k - 1].label + " (-)"
                                                                   : fmt::format("({})", k + 1);
      while (!seen.insert(label).second) label.push_back('\'');
      labels.append(",").append(js_string(label));
      if (k) colors.append(","), dashed.append(",");
      colors.append(js_string(p.series[k].color));
      dashed.append(p.series[k].dashed ? "true" : "false");
    }
    for (std::size_t i : rows) {
      if (!data.empty()) data += ',';
      data.append("[").append(num(x[i]));
      for (const svg::Series& s : p.series) data.append(",").append(num(s.y[i]));
      data.append("]");
    }
    std::string hlines, bands;
    for (const svg::HLine& h : p.hlines) {
      if (!hlines.empty()) hlines.append(",");
      hlines.append(fmt::format("[{},{}]", num(h.y), js_string(h.color)));
    }
    for (const svg::Band& b : p.bands) {
      if (!bands.empty()) bands.append(",");
      bands.append(fmt::format("[{},{},{},{},{},{}]", opt(b.x_lo), opt(b.x_hi), opt(b.y_lo), opt(b.y_hi),
                               js_string(b.color), num(b.opacity)));
    }
    o += fmt::format("<script>srehPlot(\"dy-{}\",{{title:{},xlabel:{},ylabel:{},labels:[{}],colors:[{}],dashed:[{}],"
                     "hlines:[{}],bands:[{}],data:[{}]}});</script>\n",
                     svg::xml_escape(p.id), js_string(p.title), js_string(axis_title(p.x)), js_string(axis_title(p.y)), labels,
                     colors, dashed, hlines, bands, data);
  }
  return o + "</div>\n";
}

} // namespace sreh::report
