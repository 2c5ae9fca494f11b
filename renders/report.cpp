#include "renders/report.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>

#include "renders/svg_plot.hpp"

namespace sreh {

namespace fs = std::filesystem;
using svg::xml_escape;

namespace {

// Manual 3.5.2 Fig. 3: target trajectory green (A), actual position black (B).
constexpr const char* kSetpointColor = "#2ca02c";
constexpr const char* kActualColor = "#111111";
constexpr const char* kLimitColor = "#d62728";

constexpr const char* kCss = R"css(
body{font-family:system-ui,-apple-system,"Segoe UI",sans-serif;margin:24px auto;max-width:1100px;color:#222;padding:0 16px}
h1{font-size:22px;margin-bottom:4px}h2{font-size:17px;margin-top:28px;border-bottom:1px solid #ddd;padding-bottom:4px}
.result{display:inline-block;padding:3px 12px;border-radius:4px;font-weight:bold;color:#fff}
.pass{background:#2e7d32}.fail{background:#c62828}
table{border-collapse:collapse;font-size:13px}td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}
th{background:#f2f2f2}td.l,th.l{text-align:left}td.ok{color:#2e7d32;font-weight:bold}td.bad{color:#c62828;font-weight:bold}
svg.plot{display:block;margin:10px 0;max-width:100%;height:auto}video{max-width:100%;background:#000}
.note{color:#666;font-size:12px}
)css";

std::string ms(double s) { return s < 0 ? std::string("&mdash;") : fmt::format("{:.1f}", s * 1e3); }

struct Columns {
  std::vector<double> t, setpoint, position, error, velocity, torque, limit_pos, limit_neg, external, supply, temperature;
  bool any_external = false;
};

Columns columns(const std::vector<TraceRow>& rows) {
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
    out += svg::to_svg(p);
  }
  {
    svg::Plot p = time_plot("p-tracking", "Tracking error (setpoint - actual)", "tracking error", "deg");
    p.series = {{"tracking error", c.t, c.error, "#1f77b4", 1.2, false}};
    if (in.tracking_limit_deg > 0) {
      p.hlines = {{in.tracking_limit_deg, "tracking limit (index 87)", kLimitColor, true}, {-in.tracking_limit_deg, "", kLimitColor, true}};
    }
    out += svg::to_svg(p);
  }
  {
    svg::Plot p = time_plot("p-velocity", "Velocity", "velocity", "deg/s");
    p.series = {{"velocity", c.t, c.velocity, "#9467bd", 1.2, false}};
    out += svg::to_svg(p);
  }
  {
    svg::Plot p = time_plot("p-torque", "Motor torque", "torque", "N m");
    p.series = {{"motor torque", c.t, c.torque, "#ff7f0e", 1.2, false},
                {"motor limit", c.t, c.limit_pos, kLimitColor, 1.0, true},
                {"", c.t, c.limit_neg, kLimitColor, 1.0, true}};
    if (c.any_external) p.series.push_back({"external torque", c.t, c.external, "#8c564b", 1.0, false});
    out += svg::to_svg(p);
  }
  {
    svg::Plot p = time_plot("p-supply", "Supply voltage", "voltage", "V");
    p.series = {{"supply", c.t, c.supply, "#17becf", 1.2, false}};
    out += svg::to_svg(p);
  }
  {
    svg::Plot p = time_plot("p-temperature", "Module temperature", "temperature", "\xC2\xB0" "C");
    p.series = {{"temperature", c.t, c.temperature, "#e377c2", 1.2, false}};
    out += svg::to_svg(p);
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
  double x_lo = 0, x_hi = 0;
  if (mv.positioning_s) {
    const double f = mv.start_s + *mv.positioning_s;
    const double span = std::max(f - b, 0.01);
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
  const double y_half = 1.15 * std::max({4.0 * mv.tolerance_deg, max_dev, 1e-3});

  svg::Plot p;
  p.id = fmt::format("p-settle-{}", i + 1);
  p.title = fmt::format("Move {} to {:.3f} deg (set {}): settling (manual 3.5.2 Fig. 3)", i + 1, mv.target_deg,
                        mv.parameter_set);
  p.x = {"time", "s", x_lo, x_hi};
  p.y = {"deviation from target", "deg", -y_half, y_half};
  p.series = {{"setpoint - target (A)", c.t, dev_setpoint, kSetpointColor, 1.5, false},
              {"actual - target (B)", c.t, dev_actual, kActualColor, 1.4, false}};
  if (mv.tolerance_deg > 0) {
    p.bands.push_back({{}, {}, -mv.tolerance_deg, mv.tolerance_deg,
                       fmt::format("tolerance window (5) +-{:g} deg", mv.tolerance_deg), "#2ca02c", 0.14});
  }
  p.vlines.push_back({b, "(b) trajectory end", "#555555"});
  if (mv.positioning_s) {
    const double f = mv.start_s + *mv.positioning_s;
    if (mv.wait_ms > 0) {
      p.bands.push_back({f - mv.wait_ms * 1e-3, f, {}, {}, fmt::format("waiting time (3) {:g} ms", mv.wait_ms), "#1f77b4", 0.12});
    }
    p.vlines.push_back({f, "(f) complete", "#1565c0"});
  } else {
    p.vlines.push_back({x_hi, "not completed", kLimitColor});
  }
  return svg::to_svg(p);
}

} // namespace

std::string report_html(const ReportInput& in) {
  const Columns c = columns(in.trace);
  std::string o;
  o.reserve(64 * 1024);
  o += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  o += fmt::format("<title>sreh-twin: {}</title>\n<style>{}</style>\n</head>\n<body>\n", xml_escape(in.scenario_name), kCss);
  o += fmt::format("<h1>{}</h1>\n<p><span class=\"result {}\">{}</span></p>\n", xml_escape(in.scenario_name), in.passed ? "pass" : "fail",
                   in.passed ? "PASSED" : "FAILED");

  o += "<h2>Expectations</h2>\n";
  if (in.checks.empty()) {
    o += "<p class=\"note\">No expectations in this scenario.</p>\n";
  } else {
    o += "<table id=\"checks\">\n<tr><th class=\"l\">expectation</th><th>result</th></tr>\n";
    for (const ReportCheck& ch : in.checks) {
      o += fmt::format("<tr><td class=\"l\">{}</td><td class=\"{}\">{}</td></tr>\n", xml_escape(ch.description), ch.passed ? "ok" : "bad",
                       ch.passed ? "pass" : "FAIL");
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
                       m.max_tracking_error_deg, m.completed() ? "ok" : "bad", m.completed() ? "yes" : "no");
    }
    o += "</table>\n";
  }

  if (!in.video_file.empty()) {
    o += fmt::format("<h2>Video</h2>\n<video src=\"{}\" controls preload=\"metadata\" width=\"960\"></video>\n", xml_escape(in.video_file));
  }

  o += "<h2>Over time</h2>\n";
  if (in.trace.empty()) {
    o += "<p class=\"note\">No trace was recorded.</p>\n";
  } else {
    o += overview_plots(in, c);
  }

  if (!in.moves.empty() && !in.trace.empty()) {
    o += "<h2>Settling per move (manual 3.5.2 Fig. 3)</h2>\n";
    o += "<p class=\"note\">(b) target trajectory completed; (5) tolerance window; (3) waiting time; (f) positioning complete.</p>\n";
    const std::size_t n = std::min(in.moves.size(), kMaxSettlingPlots);
    for (std::size_t i = 0; i < n; ++i) o += settling_plot(in, c, i);
    if (in.moves.size() > n) {
      o += fmt::format("<p class=\"note\">Settling plots of moves {} to {} left out; the table lists them all.</p>\n", n + 1, in.moves.size());
    }
  }
  o += "</body>\n</html>\n";
  return o;
}

void write_file_atomically(const fs::path& path, const std::string& text) {
  const fs::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) {
      std::error_code ignored;
      fs::remove(tmp, ignored);
      throw std::runtime_error("cannot write " + tmp.string());
    }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw std::runtime_error("cannot write " + path.string() + ": " + ec.message());
  }
}

fs::path write_report(const fs::path& dir, const ReportInput& in) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) throw std::runtime_error("cannot create report directory " + dir.string());
  const fs::path index = dir / "index.html";
  write_file_atomically(index, report_html(in));
  return index;
}

} // namespace sreh
