#include "renders/report.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <ostream>
#include <stdexcept>

#include <fmt/format.h>

#include "io/atomic_file.hpp"
#include "io/html_page.hpp"
#include "renders/figure.hpp"
#include "renders/svg_plot.hpp"

namespace sreh {

namespace fs = std::filesystem;
using svg::xml_escape;

namespace {

// Manual 3.5.2 Fig. 3: target trajectory green (A), actual position black (B).
constexpr const char* kSetpointColor = "#2ca02c";
constexpr const char* kActualColor = "#111111";
constexpr const char* kLimitColor = "#d62728";


std::string ms(double s) { return s < 0 ? std::string("&mdash;") : fmt::format("{:.1f}", s * 1e3); }

struct Columns {
  std::vector<double> t, setpoint, position, error, velocity, torque, limit_pos, limit_neg, external, supply, temperature;
  bool any_external = false;
};

Columns columns(std::span<const TraceRow> rows) {
  Columns c;
  for (const TraceRow& r : rows) {
    c.t.push_back(r.t_s);
    c.setpoint.push_back(r.setpoint_deg);
    c.position.push_back(r.position_deg);
    c.error.push_back(r.tracking_error_deg);
    c.velocity.push_back(r.velocity_dps);
    c.torque.push_back(r.torque_Nm);
    c.limit_pos.push_back(std::abs(r.torque_limit_Nm));
    c.limit_neg.push_back(-std::abs(r.torque_limit_Nm));
    c.external.push_back(r.external_torque_Nm);
    c.supply.push_back(r.supply_V);
    c.temperature.push_back(r.temperature_C);
    c.any_external = c.any_external || r.external_torque_Nm != 0;
  }
  return c;
}

svg::Plot time_plot(const std::string& id, const std::string& title, const std::string& y_label, const std::string& y_unit) {
  svg::Plot p;
  p.id = id;
  p.title = title;
  p.x = {"time", "s", {}, {}};
  p.y = {y_label, y_unit, {}, {}};
  return p;
}

std::string overview_plots(const ReportInput& in, const Columns& c) {
  std::string out;
  {
    svg::Plot p = time_plot("p-position", "Setpoint and actual position", "position", "deg");
    p.series = {{"setpoint (A)", c.t, c.setpoint, kSetpointColor, 1.5, false}, {"actual (B)", c.t, c.position, kActualColor, 1.2, false}};
    out += report::figure(p);
  }
  {
    svg::Plot p = time_plot("p-tracking", "Tracking error (setpoint - actual)", "tracking error", "deg");
    p.series = {{"tracking error", c.t, c.error, "#1f77b4", 1.2, false}};
    if (in.tracking_limit_deg > 0) {
      // The data sets the scale; the limit is drawn, or named at the edge when off scale.
      p.hlines = {{in.tracking_limit_deg, "tracking limit (index 87)", kLimitColor, true, false},
                  {-in.tracking_limit_deg, "", kLimitColor, true, false}};
    }
    out += report::figure(p);
  }
  {
    svg::Plot p = time_plot("p-velocity", "Velocity", "velocity", "deg/s");
    p.series = {{"velocity", c.t, c.velocity, "#9467bd", 1.2, false}};
    out += report::figure(p);
  }
  {
    svg::Plot p = time_plot("p-torque", "Motor torque", "torque", "N m");
    p.series = {{"motor torque", c.t, c.torque, "#ff7f0e", 1.2, false},
                {"motor limit", c.t, c.limit_pos, kLimitColor, 1.0, true},
                {"", c.t, c.limit_neg, kLimitColor, 1.0, true}};
    if (c.any_external) p.series.push_back({"external torque", c.t, c.external, "#8c564b", 1.0, false});
    out += report::figure(p);
  }
  {
    svg::Plot p = time_plot("p-supply", "Supply voltage", "voltage", "V");
    p.series = {{"supply", c.t, c.supply, "#17becf", 1.2, false}};
    out += report::figure(p);
  }
  {
    svg::Plot p = time_plot("p-temperature", "Module temperature", "temperature", "\xC2\xB0" "C");
    p.series = {{"temperature", c.t, c.temperature, "#e377c2", 1.2, false}};
    out += report::figure(p);
  }
  return out;
}

// Manual 3.5.2 Fig. 3 for one move: actual - target around the end of the
// trajectory (b), the tolerance window (5), the waiting time (3) ending at
// completion (f).
std::string settling_plot(const ReportInput& in, const Columns& c, std::size_t i) {
  const MoveRecord& mv = in.moves[i];
  const double b = mv.start_s + mv.travel_s;
  const double t_end = c.t.empty() ? b : c.t.back();
  const double wait_s = mv.wait_ms * 1e-3;  // the move's own set (issue 13)
  const double tol = mv.tolerance_deg;
  double x_lo = 0, x_hi = 0;
  if (mv.positioning_s) {
    const double f = mv.start_s + *mv.positioning_s;
    const double span = std::max({f - b, wait_s, 0.01});
    x_lo = b - 0.3 * span;
    x_hi = f + 0.3 * span;
  } else {
    x_lo = b - 0.01;
    x_hi = std::max(b + std::max(0.2, mv.travel_s), b + 0.01);
  }
  x_hi = std::min(x_hi, std::max(t_end, x_lo + 1e-3));

  std::vector<double> dev_actual(c.t.size()), dev_setpoint(c.t.size());
  double max_dev = 0;
  for (std::size_t k = 0; k < c.t.size(); ++k) {
    dev_actual[k] = c.position[k] - mv.target_deg;
    dev_setpoint[k] = c.setpoint[k] - mv.target_deg;
    if (c.t[k] >= b && c.t[k] <= x_hi) max_dev = std::max(max_dev, std::abs(dev_actual[k]));
  }
  // Scaled to the tolerance window (issue 16): +-3 windows; larger
  // excursions leave the plot at its edge.
  const double y_half = tol > 0 ? 3.0 * tol : 1.15 * std::max(max_dev, 1e-3);

  svg::Plot p;
  p.id = fmt::format("p-settle-{}", i + 1);
  p.title = fmt::format("Move {} to {:.3f} deg (set {}): settling (manual 3.5.2 Fig. 3)", i + 1, mv.target_deg,
                        mv.parameter_set);
  p.x = {"time", "s", x_lo, x_hi};
  p.y = {"deviation from target", "deg", -y_half, y_half};
  p.series = {{"setpoint - target (A)", c.t, dev_setpoint, kSetpointColor, 1.5, false},
              {"actual - target (B)", c.t, dev_actual, kActualColor, 1.4, false}};
  if (tol > 0) {
    p.bands.push_back({{}, {}, -tol, tol, fmt::format("tolerance window (5) +-{:.3g} deg", tol), "#2ca02c", 0.14});
  }
  p.vlines.push_back({b, "(b)", "#555555"});
  if (mv.positioning_s) {
    const double f = mv.start_s + *mv.positioning_s;
    if (wait_s > 0) {
      p.bands.push_back({f - wait_s, f, {}, {}, fmt::format("waiting time (3) {:g} ms", wait_s * 1e3), "#1f77b4", 0.12});
    }
    p.vlines.push_back({f, "(f) complete", "#1565c0"});
  } else {
    p.vlines.push_back({x_hi, "not completed", kLimitColor});
  }
  return svg::to_svg(p);
}

std::string summary(const ReportInput& in) {
  std::size_t held = 0, completed = 0;
  for (const ReportCheck& ch : in.checks) held += ch.passed ? 1 : 0;
  for (const MoveRecord& m : in.moves) completed += m.completed() ? 1 : 0;
  std::string o = fmt::format("<p><span class=\"result {}\">{}</span> {} of {} checks held; {} moves ({} completed); {:.3f} s simulated; "
                              "max tracking error {:.4f} deg</p>\n",
                              in.passed ? "pass" : "fail", in.passed ? "PASSED" : "FAILED", held, in.checks.size(), in.moves.size(),
                              completed, in.sim_time_s, in.max_tracking_error_deg);
  if (held < in.checks.size()) {
    o += "<ul class=\"failed\" id=\"failed\">\n";
    for (const ReportCheck& ch : in.checks) {
      if (ch.passed) continue;
      o += fmt::format("<li>step {}{}: {} &mdash; got {} at t = {:.3f} s</li>\n", xml_escape(ch.step),
                       ch.line > 0 ? fmt::format(" (line {})", ch.line) : std::string(), xml_escape(ch.description),
                       xml_escape(ch.actual.empty() ? std::string("-") : ch.actual), ch.t_s);
    }
    o += "</ul>\n";
  }
  if (!in.command_line.empty() || !in.version.empty()) {
    o += fmt::format("<p class=\"note\">sreh-twin {}</p><code class=\"cmd\" id=\"command\">{}</code>\n", xml_escape(in.version),
                     xml_escape(in.command_line));
  }
  return o;
}

} // namespace

std::string report_html(const ReportInput& in, const std::string& video_name) {
  const Columns c = columns(in.trace);
  std::string o;
  o.reserve(64 * 1024);
  o += fmt::format("<h1>{}</h1>\n", xml_escape(in.scenario_name));
  o += summary(in);

  o += "<h2>Expectations</h2>\n";
  if (in.checks.empty()) {
    o += "<p class=\"note\">No expectations in this scenario.</p>\n";
  } else {
    o += "<table id=\"checks\">\n<tr><th>step</th><th class=\"l\">expectation</th><th class=\"l\">observed</th><th>result</th></tr>\n";
    for (const ReportCheck& ch : in.checks) {
      o += fmt::format("<tr><td>{}</td><td class=\"l\">{}</td><td class=\"l\">{}</td><td class=\"{}\">{}</td></tr>\n", xml_escape(ch.step),
                       xml_escape(ch.description), xml_escape(ch.actual), ch.passed ? "okc" : "badc", ch.passed ? "pass" : "FAIL");
    }
    o += "</table>\n";
  }

  o += "<h2>Moves (manual 3.5.2)</h2>\n";
  if (in.moves.empty()) {
    o += "<p class=\"note\">No move command was executed.</p>\n";
  } else {
    o += "<table id=\"moves\">\n<tr><th>#</th><th>start [s]</th><th>target [deg]</th><th>travel time (1) [ms]</th>"
         "<th>settling time (2) [ms]</th><th>positioning time (4) [ms]</th><th>max tracking error [deg]</th><th>completed</th></tr>\n";
    for (std::size_t i = 0; i < in.moves.size(); ++i) {
      const MoveRecord& m = in.moves[i];
      o += fmt::format("<tr><td>{}</td><td>{:.3f}</td><td>{:.3f}</td><td>{}</td><td>{}</td><td>{}</td><td>{:.4f}</td><td class=\"{}\">{}</td></tr>\n", i + 1,
                       m.start_s, m.target_deg, ms(m.travel_s), ms(m.settling_s.value_or(-1)), ms(m.positioning_s.value_or(-1)),
                       m.max_tracking_error_deg, m.completed() ? "okc" : "badc", m.completed() ? "yes" : "no");
    }
    o += "</table>\n";
  }

  if (!video_name.empty()) {
    o += "<h2>Video</h2>\n";
    if (video_name.ends_with(".gif")) {
      o += fmt::format("<img class=\"video\" src=\"{}\" alt=\"video of the run\" width=\"960\">\n", xml_escape(video_name));
    } else {
      o += fmt::format("<video id=\"video\" src=\"{}\" controls muted preload=\"metadata\" width=\"960\"></video>\n", xml_escape(video_name));
    }
    o += "<p class=\"note\">Moves are slowed down to at least 2 s on screen and long idle stretches sped up; the "
         "overlay and the banner give the time scale (docs/assumptions/renders.md A-RENDERS-12).</p>\n";
  }

  o += "<h2 id=\"over-time\">Over time</h2>\n";
  if (in.trace.empty()) {
    o += "<p class=\"note\">No trace was recorded.</p>\n";
  } else {
    o += overview_plots(in, c);
  }

  if (!in.moves.empty() && !in.trace.empty()) {
    o += "<h2 id=\"settling\">Settling per move (manual 3.5.2 Fig. 3)</h2>\n";
    o += "<p class=\"note\">(b) target trajectory completed; (5) tolerance window; (3) waiting time; (f) positioning complete.</p>\n";
    const std::size_t n = std::min(in.moves.size(), kMaxSettlingPlots);
    for (std::size_t i = 0; i < n; ++i) o += settling_plot(in, c, i);
    if (in.moves.size() > n) {
      o += fmt::format("<p class=\"note\">Settling plots of moves {} to {} left out; the table lists them all.</p>\n", n + 1, in.moves.size());
    }
  }
  return io::html_page("sreh-twin: " + in.scenario_name, report::page_head(), o);
}

fs::path write_report(const fs::path& dir, const ReportInput& in) {
  io::make_output_folder(dir.string());
  std::string video_name;
  if (!in.video_source.empty()) { // copied in whole, so the folder can move (issue 16)
    std::string ext = in.video_source.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    video_name = "video" + ext;
    std::ifstream src(in.video_source, std::ios::binary);
    if (!src) throw std::runtime_error("cannot read the video " + in.video_source.string());
    io::write_file_atomic((dir / video_name).string(), [&](std::ostream& out) { out << src.rdbuf(); });
  }
  const fs::path index = dir / "index.html";
  const std::string html = report_html(in, video_name);
  io::write_file_atomic(index.string(), [&](std::ostream& out) { out << html; });
  return index;
}

} // namespace sreh
