#include "renders/report.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <ostream>
#include <sstream>
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

struct Columns {
  std::vector<double> t, setpoint, position, error, velocity, torque, limit_pos, limit_neg, external, supply, temperature;
  bool any_external = false;
};

void append(Columns& c, const TraceRow& r) {
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

// Calls f(row) for rows [begin, end), read back in pieces.
template <typename F>
void for_rows(ReportRecorder& run, std::size_t begin, std::size_t end, F&& f) {
  std::vector<TraceRow> chunk(std::min<std::size_t>(end - begin, 4096));
  for (std::size_t at = begin; at < end; at += chunk.size()) {
    const std::size_t n = std::min(chunk.size(), end - at);
    run.read_rows(at, {chunk.data(), n});
    for (std::size_t k = 0; k < n; ++k) f(chunk[k]);
  }
}

// The values a plot draws from a row (the -limit is the +limit mirrored).
constexpr std::size_t kPlotted = 9;
std::array<double, kPlotted> plotted(const TraceRow& r) {
  return {r.setpoint_deg, r.position_deg,   r.tracking_error_deg, r.velocity_dps, r.torque_Nm, std::abs(r.torque_limit_Nm),
          r.external_torque_Nm, r.supply_V, r.temperature_C};
}

// Min/max decimation of a long stretch, one pass over rows in time order:
// in each of `columns` equal slices of [lo, hi] the first and last row and
// the rows where a plotted value is smallest and largest, in time order.
// What a min/max plot draws of the slice; the plots' own decimation (1500
// columns or the plot's width) then works on these rows as on all of them.
class MinMaxRows {
 public:
  MinMaxRows(double lo, double hi, int columns) : lo_(lo), scale_(columns / std::max(hi - lo, 1e-12)) {}
  void add(const TraceRow& r) {
    const long col = static_cast<long>(std::floor((r.t_s - lo_) * scale_));
    const auto v = plotted(r);
    if (col != col_ || picks_.empty()) {
      flush();
      col_ = col;
      picks_.assign(2 + 2 * kPlotted, {index_, r});
      min_ = max_ = v;
    }
    picks_[1] = {index_, r}; // last
    for (std::size_t s = 0; s < kPlotted; ++s) {
      if (v[s] < min_[s]) min_[s] = v[s], picks_[2 + 2 * s] = {index_, r};
      if (v[s] > max_[s]) max_[s] = v[s], picks_[3 + 2 * s] = {index_, r};
    }
    ++index_;
  }
  Columns take() {
    flush();
    return std::move(out_);
  }

 private:
  void flush() {
    std::sort(picks_.begin(), picks_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t k = 0; k < picks_.size(); ++k) {
      if (k == 0 || picks_[k].first != picks_[k - 1].first) append(out_, picks_[k].second);
    }
    picks_.clear();
  }
  double lo_, scale_;
  long col_ = 0;
  std::size_t index_ = 0;
  std::vector<std::pair<std::size_t, TraceRow>> picks_;
  std::array<double, kPlotted> min_{}, max_{};
  Columns out_;
};

// Twice the 1500 columns the zoomable figures keep.
constexpr int kDecimationColumns = 3000;

// Rows [begin, end) as plot columns: every row up to kReportFullRateRows,
// else their min/max decimation over [t(begin), t(end - 1)].
Columns columns(ReportRecorder& run, std::size_t begin, std::size_t end) {
  Columns c;
  if (end <= begin) return c;
  if (end - begin <= kReportFullRateRows) {
    for_rows(run, begin, end, [&](const TraceRow& r) { append(c, r); });
    return c;
  }
  MinMaxRows keep(run.row(begin).t_s, run.row(end - 1).t_s, kDecimationColumns);
  bool any_external = false;
  for_rows(run, begin, end, [&](const TraceRow& r) {
    keep.add(r);
    any_external = any_external || r.external_torque_Nm != 0;
  });
  c = keep.take();
  c.any_external = any_external;
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

std::string overview_plots(const ReportSummary& in, const Columns& c) {
  std::string out;
  {
    svg::Plot p = time_plot("p-position", "Setpoint and actual position", "position", "deg");
    // The setpoint dashed and wider under the actual (issue 29): both stay visible where they coincide.
    p.series = {{"setpoint (A), dashed", c.t, c.setpoint, kSetpointColor, 2.2, true},
                {"actual (B)", c.t, c.position, kActualColor, 1.2, false}};
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
// Only the rows of the plotted stretch are read back, with one row either
// side so that the curves run to the edges.
std::string settling_plot(ReportRecorder& run, const MoveRecord& mv, std::size_t i, double t_end) {
  const double b = mv.start_s + mv.travel_s;
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
  const std::size_t first = run.lower_bound(x_lo), last = run.upper_bound(x_hi);
  const Columns c = columns(run, first > 0 ? first - 1 : 0, std::min(last + 1, run.rows()));

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
  p.series = {{"setpoint - target (A), dashed", c.t, dev_setpoint, kSetpointColor, 2.2, true},
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

void write_summary(std::ostream& out, const ReportSummary& in, ReportRecorder& run) {
  out << fmt::format("<p><span class=\"result {}\">{}</span> {} of {} checks held; {} moves ({} completed); {:.3f} s simulated; "
                     "max tracking error {:.4f} deg</p>\n",
                     in.passed ? "pass" : "fail", in.passed ? "PASSED" : "FAILED", run.checks_held(), run.checks(), run.moves(),
                     run.moves_completed(), in.sim_time_s, in.max_tracking_error_deg);
  if (!in.hints.empty()) {
    out << "<ul class=\"hints\" id=\"hints\">\n";
    for (const std::string& h : in.hints) out << "<li>" << xml_escape(h) << "</li>\n";
    out << "</ul>\n";
  }
  if (run.checks_held() < run.checks()) {
    out << "<ul class=\"failed\" id=\"failed\">\n";
    run.copy_failed_items(out);
    out << "</ul>\n";
  }
  if (!in.command_line.empty() || !in.version.empty()) {
    out << fmt::format("<p class=\"note\">sreh-twin {}</p><code class=\"cmd\" id=\"command\">{}</code>\n", xml_escape(in.version),
                       xml_escape(in.command_line));
  }
}

} // namespace

void write_report_html(std::ostream& out, const ReportSummary& in, ReportRecorder& run, const std::string& video_name) {
  out << io::html_page_open("sreh-twin: " + in.scenario_name, report::page_head());
  out << fmt::format("<h1>{}</h1>\n", xml_escape(in.scenario_name));
  write_summary(out, in, run);

  out << "<h2>Expectations</h2>\n";
  if (run.checks() == 0) {
    out << "<p class=\"note\">No expectations in this scenario.</p>\n";
  } else {
    out << "<table id=\"checks\">\n<tr><th>step</th><th class=\"l\">expectation</th><th class=\"l\">observed</th><th>result</th></tr>\n";
    run.copy_check_rows(out);
    out << "</table>\n";
  }

  out << "<h2>Moves (manual 3.5.2)</h2>\n";
  if (run.moves() == 0) {
    out << "<p class=\"note\">No move command was executed.</p>\n";
  } else {
    out << "<table id=\"moves\">\n<tr><th>#</th><th>start [s]</th><th>target [deg]</th><th>travel time (1) [ms]</th>"
           "<th>settling time (2) [ms]</th><th>positioning time (4) [ms]</th><th>max tracking error [deg]</th><th>completed</th></tr>\n";
    run.copy_move_rows(out);
    out << "</table>\n";
  }

  if (!video_name.empty()) {
    out << "<h2>Video</h2>\n";
    if (video_name.ends_with(".gif")) {
      out << fmt::format("<img class=\"video\" src=\"{}\" alt=\"video of the run\" width=\"960\">\n", xml_escape(video_name));
    } else {
      out << fmt::format("<video id=\"video\" src=\"{}\" controls muted preload=\"metadata\" width=\"960\"></video>\n",
                         xml_escape(video_name));
    }
    out << "<p class=\"note\">Moves are slowed down to at least 2 s on screen and long idle stretches sped up; the "
           "overlay and the banner give the time scale (docs/assumptions/renders.md A-RENDERS-12).</p>\n";
  }

  out << "<h2 id=\"over-time\">Over time</h2>\n";
  if (run.rows() == 0) {
    out << "<p class=\"note\">No trace was recorded.</p>\n";
  } else {
    out << overview_plots(in, columns(run, 0, run.rows()));
  }

  if (run.moves() > 0 && run.rows() > 0) {
    out << "<h2 id=\"settling\">Settling per move (manual 3.5.2 Fig. 3)</h2>\n";
    out << "<p class=\"note\">(b) target trajectory completed; (5) tolerance window; (3) waiting time; (f) positioning complete.</p>\n";
    const double t_end = run.row(run.rows() - 1).t_s;
    const std::vector<MoveRecord>& zoomed = run.zoomed_moves();
    for (std::size_t i = 0; i < zoomed.size(); ++i) out << settling_plot(run, zoomed[i], i, t_end);
    if (run.moves() > zoomed.size()) {
      out << fmt::format("<p class=\"note\">Settling plots of moves {} to {} left out; the table lists them all.</p>\n",
                         zoomed.size() + 1, run.moves());
    }
  }
  out << io::html_page_close();
}

namespace {

// The in-memory run, recorded like a running one.
void record(const ReportInput& in, ReportRecorder& run) {
  for (const TraceRow& r : in.trace) run.add_row(r);
  for (const ReportCheck& ch : in.checks) run.add_check(ch);
  for (const MoveRecord& m : in.moves) run.add_move(m);
}

} // namespace

std::string report_html(const ReportInput& in, const std::string& video_name) {
  ReportRecorder run;
  record(in, run);
  std::ostringstream out;
  write_report_html(out, in, run, video_name);
  return out.str();
}

fs::path write_report(const fs::path& dir, const ReportSummary& in, ReportRecorder& run) {
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
  io::write_file_atomic(index.string(), [&](std::ostream& out) { write_report_html(out, in, run, video_name); });
  return index;
}

fs::path write_report(const fs::path& dir, const ReportInput& in) {
  ReportRecorder run;
  record(in, run);
  return write_report(dir, in, run);
}

} // namespace sreh
