// The sizing report of a cycle (`size --cycle ... --report DIR`) and the
// temperature plot both reports share (issue 17): renders' figure/SVG code
// as the single-move report, in the one page shell (io/html_page.hpp).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "io/atomic_file.hpp"
#include "io/html_page.hpp"
#include "sizing/cycle_output.hpp"
#include "sizing/output.hpp"
#include "sizing/report.hpp"
#include "sizing/report_parts.hpp"
#include "sizing/thermal_estimate.hpp"
#include "sizing/uncertainty.hpp"

#if SREH_SIZING_WITH_REPORT
#include "device_logic/motor_model.hpp"
#include "device_logic/units.hpp"
#include "renders/figure.hpp"
#include "renders/svg_plot.hpp"
#endif

namespace sreh::sizing {

#if SREH_SIZING_WITH_REPORT
namespace {

using svg::xml_escape;

using report_parts::colour;
using report_parts::row;

std::string when(const std::optional<double>& s) { return s ? fmt::format("{:.0f} s", *s) : std::string("never"); }

// Speed-torque plane (manual 3.5.3): the motor's capability at the supply
// voltage (and at 16 / 24 / 32 V for comparison), every trace sample of the
// last repetition as an operating point (one colour per move), and the RMS
// point (RMS torque at the RMS speed) against the continuous torque.
std::string cycle_speed_torque_plot(const CycleRequest& rq, const CycleEvaluation& e) {
  svg::Plot p = report_parts::speed_torque_plane(
      "cycle-speed-torque",
      fmt::format("Speed-torque plane: operating points of the cycle, motor envelope at {:.1f} V", rq.world.supply.voltage_V));
  auto envelope = [&rq](double volts, const std::string& label, const char* color, double width, bool dashed) {
    return report_parts::motor_envelope(rq.world.module.drive.motor, volts, 1.02, label, color, width, dashed);
  };
  p.series.push_back(envelope(rq.world.supply.voltage_V, fmt::format("envelope {:.1f} V", rq.world.supply.voltage_V), "#d62728", 1.8, false));
  for (double v : {min_voltage_V(), max_voltage_V()}) { // the index 85 window (manual 6.2)
    if (std::abs(v - rq.world.supply.voltage_V) > 0.5) p.series.push_back(envelope(v, fmt::format("envelope {:.0f} V", v), "#bbbbbb", 1.0, true));
  }
  double sq_speed = 0;
  std::size_t n = 0;
  std::size_t move_no = 0;
  for (std::size_t i = 0; i < e.segments.size(); ++i) {
    const SegmentResult& s = e.segments[i];
    if (s.kind != "move") continue;
    svg::Series pts{fmt::format("move {} (segment {})", ++move_no, i + 1), {}, {}, colour(move_no - 1), 1.0, false, true};
    for (std::size_t r = s.row_from; r < s.row_to && r < e.trace.size(); ++r) {
      pts.x.push_back(std::abs(e.trace[r].velocity_dps));
      pts.y.push_back(std::abs(e.trace[r].torque_Nm));
    }
    if (!pts.x.empty()) p.series.push_back(std::move(pts));
  }
  for (std::size_t r = e.last_repetition_row; r < e.trace.size(); ++r) {
    sq_speed += e.trace[r].velocity_dps * e.trace[r].velocity_dps;
    ++n;
  }
  const double rms_speed = n ? std::sqrt(sq_speed / static_cast<double>(n)) : 0.0;
  report_parts::add_rms_point(p, rms_speed, e.rms_torque_Nm, e.torque_capability_Nm, e.continuous_torque_Nm);
  return report::figure(p, false);
}

// Positioning time per segment: travel (planned) and settling as stacked
// bars, dwells as their own bars.
std::string segment_time_plot(const CycleEvaluation& e) {
  svg::Plot p;
  p.id = "segment-times";
  p.title = "Time per segment (last repetition): travel, settling, handshake, dwell";
  p.x = {"segment", "#", 0.5, static_cast<double>(e.segments.size()) + 0.5};
  p.y = {"time", "s", 0.0, {}};
  double top = 0;
  bool first = true, first_dwell = true; // one legend entry per colour
  for (std::size_t i = 0; i < e.segments.size(); ++i) {
    const SegmentResult& s = e.segments[i];
    const double x0 = static_cast<double>(i + 1) - 0.35, x1 = static_cast<double>(i + 1) + 0.35;
    if (s.kind == "move") {
      const double settle = std::max(0.0, s.settling_s);
      p.bands.push_back({x0, x1, 0.0, s.travel_s, first ? "travel" : "", "#1f77b4", 0.8});
      p.bands.push_back({x0, x1, s.travel_s, s.travel_s + settle, first ? "settling" : "", "#ff7f0e", 0.8});
      p.bands.push_back({x0, x1, s.travel_s + settle, s.travel_s + settle + e.handshake_s, first ? "handshake" : "",
                         "#7f7f7f", 0.8});
      top = std::max(top, s.travel_s + settle + e.handshake_s);
      first = false;
    } else if (s.kind == "dwell") {
      p.bands.push_back({x0, x1, 0.0, s.duration_s, first_dwell ? "dwell" : "", "#2ca02c", 0.5});
      first_dwell = false;
      top = std::max(top, s.duration_s);
    }
  }
  // Invisible series so that the axes span the bars (legend entries for the colours come from the first move).
  p.series.push_back({"", {0.5, static_cast<double>(e.segments.size()) + 0.5}, {0.0, top * 1.05}, "#ffffff", 0.0, false, false});
  return report::figure(p, false);
}

} // namespace

std::string temperature_plot(double mean_loss_W, double ambient_C, double thermal_margin_K,
                             const std::optional<double>& time_to_trip_s, const ThermalConstants& constants,
                             const UncertaintyResult* steady_band) {
  // Long enough to see the steady state (housing: 20 min) or the trip.
  const double duration_s = time_to_trip_s ? std::max(60.0, 1.3 * *time_to_trip_s) : 6000.0;
  const std::vector<TemperaturePoint> curve = temperature_curve(mean_loss_W, ambient_C, duration_s, duration_s / 600.0, constants);
  svg::Plot p;
  p.id = "temperature";
  p.title = "Module temperature under continuous cycling, from ambient (twin's thermal model, mean loss)";
  p.x = {"time", "s", 0.0, {}};
  // Always up to past the 75 degC trip (issue 29): the curve is read against
  // the warning and the trip, whatever its own range.
  double top_C = kTemperatureTrip_C + 5.0;
  for (const TemperaturePoint& q : curve) top_C = std::max(top_C, q.C + 5.0);
  p.y = {"temperature", "degC", {}, top_C};
  svg::Series s{fmt::format("sensor ({:.2f} W)", mean_loss_W), {}, {}, "#d62728", 1.6, false, false};
  for (const TemperaturePoint& q : curve) {
    s.x.push_back(q.t_s);
    s.y.push_back(q.C);
  }
  p.series.push_back(std::move(s));
  p.hlines = {{kTemperatureWarning_C, "70 degC warning (115.1)", "#ff7f0e", true},
              {kTemperatureTrip_C, "75 degC trip (error 114.3)", "#d62728", true},
              {kTemperatureWarning_C - thermal_margin_K, fmt::format("required margin {:.0f} K", thermal_margin_K),
               "#2ca02c", true}};
  if (steady_band && steady_band->banded > 0) { // issue 26: where the curve may level off on the sampled models
    const Band& b = steady_band->max_temperature_C;
    p.bands.push_back({{}, {}, b.lo, b.hi, "steady temperature over the sampled models", "#d62728", 0.12});
    p.y.max = std::max(*p.y.max, b.hi + 5.0);
  }
  return report::figure(p);
}

std::string cycle_report_html(const CycleRequest& rq, const CycleResult& r, const UncertaintyResult* u) {
  const CycleEvaluation& e = r.evaluation;
  const std::string title = fmt::format("Sizing: cycle {}", std::filesystem::path(rq.file).filename().string());
  std::string o = report_parts::page_head(title);
  // The verdict first (issue 29): the same block as the single move's.
  double speed_dps = 0, load_gcm2 = 0;
  for (const ParameterSetValues& set : e.sets) speed_dps = std::max(speed_dps, set.tidy.speed_dps);
  for (const SegmentResult& s : e.segments) {
    if (s.kind == "move") load_gcm2 = std::max(load_gcm2, s.load_gcm2);
  }
  o += report_parts::verdict_block({&e, e.feasible, e.binding_limit, rq.thermal_margin_K, rq.world.thermal.ambient_C, speed_dps, load_gcm2, u});
  if (u) {
    const WorstMove w = worst_move(e);
    o += report_parts::uncertainty_section(*u, {w.positioning_s, w.settling_s, e.peak_torque_Nm, e.steady_temperature_C, e.cycle_s});
  }
  o += "<h2>Numbers</h2>\n<table>\n";
  o += row("supply / ambient / mounting", fmt::format("{:.1f} V / {:.1f} degC / tilt {} deg", rq.world.supply.voltage_V, rq.world.thermal.ambient_C,
                                                      rq.world.mounting_tilt_deg));
  o += row("cycle", e.completed ? fmt::format("{:.4f} s, {:.1f} cycles/min (handshake {:.0f} ms per move)", e.cycle_s,
                                              e.cycles_per_min, e.handshake_s * 1e3)
                                : std::string("not completed"));
  o += row("peak / RMS torque", fmt::format("{:.3f} / {:.3f} N m (capability {:.3f}, continuous {:.3f} N m)",
                                            e.peak_torque_Nm, e.rms_torque_Nm, e.torque_capability_Nm,
                                            e.continuous_torque_Nm));
  o += row("steady temperature", fmt::format("{:.1f} degC ({:.2f} W mean loss)", e.steady_temperature_C, e.mean_loss_W));
  o += row("time to 70 degC warning / 75 degC trip", when(e.time_to_warning_s) + " / " + when(e.time_to_trip_s));
  o += row("simulations", fmt::format("{} (back-offs {})", r.simulations, r.backoffs));
  o += "</table>\n<h2>Parameter sets and ISDU writes</h2>\n<pre>";
  for (const ParameterSetValues& s : e.sets) {
    o += xml_escape(fmt::format("# set {}: {:.1f} deg/s, {:.1f} %, {:.1f} %, load {:.0f} g cm^2\n", s.set,
                                s.tidy.speed_dps, s.tidy.accel_pct, s.tidy.jerk_pct, s.load_gcm2));
  }
  for (const IsduWrite& w : all_writes(e)) o += xml_escape(isdu_write_line(w)) + "\n";
  o += "</pre>\n<h2>Segments (last repetition)</h2>\n<table>\n<tr><th>#</th><th>kind</th><th>from -> to deg</th>"
       "<th>set</th><th>load g cm^2</th><th>travel s</th><th>settling s</th><th>positioning s</th><th>duration s</th>"
       "<th>peak / RMS N m</th></tr>\n";
  for (std::size_t i = 0; i < e.segments.size(); ++i) {
    const SegmentResult& s = e.segments[i];
    if (s.kind == "move") {
      o += fmt::format("<tr><td>{}</td><td>move</td><td>{:.2f} -> {:.2f}</td><td>{}</td><td>{:.0f}</td><td>{:.4f}</td>"
                       "<td>{:.4f}</td><td>{:.4f}</td><td>{:.4f}</td><td>{:.3f} / {:.3f}</td></tr>\n",
                       i + 1, s.start_deg, s.target_deg, s.parameter_set, s.load_gcm2, s.travel_s, s.settling_s,
                       s.positioning_s, s.duration_s, s.peak_torque_Nm, s.rms_torque_Nm);
    } else {
      o += fmt::format("<tr><td>{}</td><td>{}</td><td></td><td></td><td></td><td></td><td></td><td></td><td>{:.4f}</td>"
                       "<td></td></tr>\n", i + 1, s.kind, s.duration_s);
    }
  }
  o += "</table>\n<h2>Plots</h2>\n";
  o += segment_time_plot(e);
  if (!e.trace.empty()) o += cycle_speed_torque_plot(rq, e);
  o += temperature_plot(e.mean_loss_W, rq.world.thermal.ambient_C, rq.thermal_margin_K, e.time_to_trip_s, rq.world.module.thermal, u);
  if (!e.trace.empty()) {
    svg::Plot q;
    q.id = "cycle-torque";
    q.title = "Position and motor torque over the simulated repetitions";
    q.x = {"time", "s", {}, {}};
    q.y = {"torque", "N m", {}, {}};
    svg::Series tq{"torque", {}, {}, "#ff7f0e", 1.2, false, false};
    for (const TraceRow& t : e.trace) {
      tq.x.push_back(t.t_s);
      tq.y.push_back(t.torque_Nm);
    }
    q.series.push_back(std::move(tq));
    o += report::figure(q);
    o += report::figure(report_parts::position_plot("cycle-position", e.trace));
  }
  o += "<p class=\"note\">Every figure from the twin running the cycle (docs/sizing.md \"Cycles\"); temperature from "
       "its lumped thermal model at the last repetition's mean loss (A-SIZE-6).</p>\n" + io::html_page_close();
  return o;
}

std::filesystem::path write_cycle_report(const std::filesystem::path& dir, const CycleRequest& rq, const CycleResult& r,
                                         const UncertaintyResult* u) {
  return report_parts::write_index(dir, cycle_report_html(rq, r, u));
}

#else

namespace {
[[noreturn]] void no_cycle_reports() { throw std::runtime_error("this build has no reports (SREH_WITH_RENDER=OFF)"); }
} // namespace
std::string temperature_plot(double, double, double, const std::optional<double>&, const ThermalConstants&,
                             const UncertaintyResult*) {
  no_cycle_reports();
}
std::string cycle_report_html(const CycleRequest&, const CycleResult&, const UncertaintyResult*) { no_cycle_reports(); }
std::filesystem::path write_cycle_report(const std::filesystem::path&, const CycleRequest&, const CycleResult&,
                                         const UncertaintyResult*) {
  no_cycle_reports();
}

#endif

} // namespace sreh::sizing
