#include "sizing/report.hpp"

#include "sizing/uncertainty.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <stdexcept>

#include <fmt/format.h>

#include "io/atomic_file.hpp"
#include "io/html_page.hpp"
#include "sizing/output.hpp"
#include "sizing/report_parts.hpp"

#if SREH_SIZING_WITH_REPORT
#include "device_logic/motor_model.hpp"
#include "device_logic/units.hpp"
#include "renders/figure.hpp"
#include "renders/report.hpp"
#include "renders/svg_plot.hpp"
#endif

namespace sreh::sizing {

std::vector<double> default_targets_s(const SweepResult& result) {
  double lo = INFINITY, hi = 0;
  for (const SweepPoint& p : result.points) {
    const Evaluation& e = p.result.evaluation;
    if (!e.feasible) continue;
    lo = std::min(lo, e.positioning_s);
    hi = std::max(hi, e.positioning_s);
  }
  std::vector<double> targets;
  if (!(hi > 0)) return targets;
  constexpr int kTargets = 8;
  for (int k = 0; k < kTargets; ++k) {
    // Whole milliseconds, rounded up so that the smallest target meets a point.
    const double t = std::ceil((lo + (hi - lo) * k / (kTargets - 1)) * 1000.0 - 1e-9) / 1000.0;
    if (targets.empty() || t > targets.back()) targets.push_back(t);
  }
  return targets;
}

#if SREH_SIZING_WITH_REPORT
namespace {

using svg::xml_escape;


using report_parts::colour;
using report_parts::page_head;
using report_parts::row;
using report_parts::write_index;

std::string numbers_table(const SizingRequest& rq, const SizingResult& r) {
  const Evaluation& e = r.evaluation;
  std::string o = "<table>\n";
  o += row("move", fmt::format("{} deg back and forth, dwell {} s, {} cycles", rq.angle_deg, rq.dwell_s, rq.cycles));
  o += row("load (actual, MuJoCo)", fmt::format("{:.1f} g cm^2", e.load_gcm2));
  o += row("supply / ambient", fmt::format("{:.1f} V / {:.1f} degC", rq.world.supply.voltage_V, rq.world.thermal.ambient_C));
  o += row("speed / acceleration / jerk", fmt::format("{:.1f} deg/s / {:.1f} % / {:.1f} %", e.set.setting.speed_dps,
                                                      e.set.setting.accel_pct, e.set.setting.jerk_pct));
  o += row("travel time (1)", fmt::format("{:.4f} s", e.travel_s));
  o += row("settling time (2)", fmt::format("{:.4f} s (waiting time {:.1f} ms)", e.settling_s, e.set.wait_ms));
  o += row("positioning time (4)", fmt::format("{:.4f} s", e.positioning_s));
  o += row("cycle", fmt::format("{:.4f} s, {:.1f} cycles/min", e.cycle_s, e.cycles_per_min));
  o += row("peak / RMS torque", fmt::format("{:.3f} / {:.3f} N m (capability {:.3f} N m)", e.peak_torque_Nm,
                                            e.rms_torque_Nm, e.torque_capability_Nm));
  o += row("max tracking error", fmt::format("{:.3f} deg (limit {:.1f} deg)", e.max_tracking_error_deg, e.tracking_limit_deg));
  o += row("steady temperature", fmt::format("{:.1f} degC ({:.2f} W mean loss)", e.steady_temperature_C, e.mean_loss_W));
  o += row("time to 70 degC warning",
           e.time_to_warning_s ? fmt::format("{:.0f} s", *e.time_to_warning_s) : std::string("never"));
  o += row("time to 75 degC trip (114.3)",
           e.time_to_trip_s ? fmt::format("{:.0f} s", *e.time_to_trip_s) : std::string("never"));
  o += row("simulations", fmt::format("{}", r.simulations));
  return o + "</table>\n";
}

// The motor's speed-torque capability at the sizing's supply (MotorModel,
// manual 3.5.3) with the move's operating points: motoring and braking.
std::string speed_torque_plot(const SizingRequest& rq, const Evaluation& e) {
  svg::Plot p = report_parts::speed_torque_plane(
      "speed-torque", fmt::format("Speed-torque: operating points and motor capability at {:.1f} V", rq.world.supply.voltage_V));
  const svg::Series cap = report_parts::motor_envelope(rq.world.module.drive.motor, rq.world.supply.voltage_V, 1.05, "capability (motoring)", "#d62728", 1.6, false);
  svg::Series motoring{"motoring", {}, {}, "#1f77b4", 1.0, false, true};
  svg::Series braking{"braking", {}, {}, "#ff7f0e", 1.0, false, true};
  for (const TraceRow& r : e.trace) {
    const bool brake = r.torque_Nm * r.velocity_dps < 0;
    (brake ? braking : motoring).x.push_back(std::abs(r.velocity_dps));
    (brake ? braking : motoring).y.push_back(std::abs(r.torque_Nm));
  }
  // The RMS point (issue 17): RMS torque at the RMS speed, against the continuous torque.
  double sq_speed = 0;
  for (const TraceRow& r : e.trace) sq_speed += r.velocity_dps * r.velocity_dps;
  const double rms_speed = e.trace.empty() ? 0.0 : std::sqrt(sq_speed / static_cast<double>(e.trace.size()));
  p.series = {cap, motoring, braking};
  report_parts::add_rms_point(p, rms_speed, e.rms_torque_Nm, e.torque_capability_Nm, e.continuous_torque_Nm);
  p.vlines = {{e.set.setting.speed_dps, "set speed", "#555555"}};
  return report::figure(p, false);
}

} // namespace

namespace report_parts {

const char* colour(std::size_t i) {
  static constexpr const char* kColours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                             "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
  return kColours[i % (sizeof kColours / sizeof kColours[0])];
}

std::string page_head(const std::string& title) {
  return io::html_page_open(title, report::page_head()) + fmt::format("<h1>{}</h1>\n", xml_escape(title));
}

std::string row(const std::string& name, const std::string& value) {
  return fmt::format("<tr><td class=\"l\">{}</td><td>{}</td></tr>\n", xml_escape(name), xml_escape(value));
}

std::filesystem::path write_index(const std::filesystem::path& dir, const std::string& html) {
  io::make_output_folder(dir.string());
  const std::filesystem::path index = dir / "index.html";
  io::write_file_atomic(index.string(), [&](std::ostream& out) { out << html; });
  return index;
}

svg::Plot speed_torque_plane(const std::string& id, const std::string& title) {
  svg::Plot p;
  p.id = id;
  p.title = title;
  p.x = {"speed |velocity|", "deg/s", 0.0, {}};
  p.y = {"|motor torque|", "N m", 0.0, {}};
  return p;
}

svg::Plot position_plot(const std::string& id, const std::vector<TraceRow>& rows) {
  svg::Plot p;
  p.id = id;
  p.title = "Position";
  p.x = {"time", "s", {}, {}};
  p.y = {"position", "deg", {}, {}};
  svg::Series sp{"setpoint", {}, {}, "#2ca02c", 1.5, true, false}, pos{"actual", {}, {}, "#1f77b4", 1.5, false, false};
  for (const TraceRow& r : rows) {
    sp.x.push_back(r.t_s);
    sp.y.push_back(r.setpoint_deg);
    pos.x.push_back(r.t_s);
    pos.y.push_back(r.position_deg);
  }
  p.series = {std::move(sp), std::move(pos)};
  return p;
}

svg::Series motor_envelope(const MotorModel& motor, double voltage_V, double top_factor, const std::string& label,
                           const char* color, double width, bool dashed) {
  svg::Series s{label, {}, {}, color, width, dashed, false};
  const double top_dps = top_factor * rad_to_deg(voltage_V / motor.torque_constant_Nm_per_A);
  for (int k = 0; k <= 200; ++k) {
    const double dps = top_dps * k / 200;
    const double tq = motor.max_torque_Nm(deg_to_rad(dps), voltage_V, 1.0);
    if (tq < 0) break;
    s.x.push_back(dps);
    s.y.push_back(tq);
  }
  return s;
}

void add_rms_point(svg::Plot& p, double rms_speed_dps, double rms_torque_Nm, double torque_capability_Nm,
                   double continuous_torque_Nm) {
  p.series.push_back({fmt::format("RMS point ({:.0f} deg/s, {:.3f} N m)", rms_speed_dps, rms_torque_Nm),
                      {rms_speed_dps}, {rms_torque_Nm}, "#000000", 4.0, false, true});
  p.hlines = {{kTorqueMargin * torque_capability_Nm, fmt::format("{:.0f} % of peak", 100 * kTorqueMargin), "#9467bd", true},
              {continuous_torque_Nm, "continuous torque", "#2ca02c", true}};
}

} // namespace report_parts

bool reports_available() { return true; }

std::string size_report_html(const SizingRequest& rq, const SizingResult& r, const UncertaintyResult* u,
                             const SettlingSpread* spread) {
  const Evaluation& e = r.evaluation;
  std::string o = page_head(fmt::format("Sizing: {} deg, {:.0f} g cm^2, {:.1f} V", rq.angle_deg, e.load_gcm2, rq.world.supply.voltage_V));
  // The verdict first (issue 29), from the figures the text and JSON print;
  // with --uncertainty the verdict over every sample (issue 35).
  o += report_parts::verdict_block({&e, r.feasible, r.binding_limit, rq.thermal_margin_K, rq.world.thermal.ambient_C, e.set.setting.speed_dps,
                                    e.load_gcm2, u});
  if (spread) o += report_parts::settling_spread_section(*spread);
  if (u) {
    o += report_parts::uncertainty_section(
        *u, {e.positioning_s, e.settling_s, e.peak_torque_Nm, e.steady_temperature_C, std::nullopt});
  }
  o += "<h2>Numbers (manual 3.5.2 terms)</h2>\n" + numbers_table(rq, r);
  o += "<h2>ISDU writes</h2>\n<pre>";
  for (const IsduWrite& w : e.set.writes) o += xml_escape(isdu_write_line(w)) + "\n";
  o += "</pre>\n";

  o += "<h2>Moves</h2>\n<table>\n<tr><th>#</th><th>target deg</th><th>travel s</th><th>settling s</th>"
       "<th>positioning s</th><th>max tracking error deg</th><th>completed</th></tr>\n";
  for (std::size_t i = 0; i < e.moves.size(); ++i) {
    const MoveResult& m = e.moves[i];
    o += fmt::format("<tr><td>{}</td><td>{}</td><td>{:.4f}</td><td>{:.4f}</td><td>{:.4f}</td><td>{:.4f}</td>"
                     "<td>{}</td></tr>\n",
                     i + 1, m.target_deg, m.travel_s, m.settling_s, m.positioning_s, m.max_tracking_error_deg,
                     m.completed ? "yes" : "no");
  }
  o += "</table>\n";

  if (!e.trace.empty()) {
    std::vector<double> t, vel, tq, err;
    for (const TraceRow& row_ : e.trace) {
      t.push_back(row_.t_s);
      vel.push_back(row_.velocity_dps);
      tq.push_back(row_.torque_Nm);
      err.push_back(row_.tracking_error_deg);
    }
    o += "<h2>Trace (one sample per 2 ms IO-Link cycle)</h2>\n";
    const svg::Plot p = report_parts::position_plot("position", e.trace);
    o += report::figure(p);
    svg::Plot v;
    v.id = "velocity";
    v.title = "Velocity";
    v.x = p.x;
    v.y = {"velocity", "deg/s", {}, {}};
    v.series = {{"velocity", t, vel, "#1f77b4", 1.5, false}};
    v.hlines = {{e.set.setting.speed_dps, fmt::format("set speed +-{:.1f} deg/s", e.set.setting.speed_dps), "#d62728", true},
                {-e.set.setting.speed_dps, "", "#d62728", true}};
    o += report::figure(v);
    svg::Plot q;
    q.id = "torque";
    q.title = "Motor torque";
    q.x = p.x;
    q.y = {"torque", "N m", {}, {}};
    q.series = {{"torque", t, tq, "#ff7f0e", 1.5, false}};
    const double cap = e.torque_capability_Nm, margin = kTorqueMargin * cap;
    q.hlines = {{cap, fmt::format("peak torque capability +-{:.3f} N m", cap), "#d62728", false},  {-cap, "", "#d62728", false},
                {margin, fmt::format("{:.0f} % of capability (feasibility limit)", 100 * kTorqueMargin), "#9467bd", true},
                {-margin, "", "#9467bd", true}};
    if (u && u->banded > 0) q.bands.push_back(report_parts::peak_torque_band(*u));
    o += report::figure(q);
    o += speed_torque_plot(rq, e);
    svg::Plot te;
    te.id = "tracking";
    te.title = "Tracking error";
    te.x = p.x;
    te.y = {"tracking error", "deg", {}, {}};
    te.series = {{"setpoint - actual", t, err, "#8c564b", 1.5, false}};
    te.bands = {{{}, {}, -e.set.tolerance_deg, e.set.tolerance_deg, "tolerance window", "#2ca02c", 0.15}};
    o += report::figure(te);
  }
  o += temperature_plot(e.mean_loss_W, rq.world.thermal.ambient_C, rq.thermal_margin_K, e.time_to_trip_s, rq.world.module.thermal, u);
  o += "<p class=\"note\">Travel time from the device's planner; settling and positioning simulated; torque "
       "sampled per IO-Link cycle; temperature from the twin's lumped thermal model at the cycle's mean loss "
       "(docs/assumptions/sizing.md).</p>\n" + io::html_page_close();
  return o;
}

std::filesystem::path write_size_report(const std::filesystem::path& dir, const SizingRequest& rq,
                                        const SizingResult& r, const UncertaintyResult* u, const SettlingSpread* spread) {
  return write_index(dir, size_report_html(rq, r, u, spread));
}

std::string sweep_report_html(const SweepRequest& rq, const SweepResult& result, const std::vector<double>& targets) {
  std::string o = page_head(fmt::format("Sizing sweep: {} points", result.points.size()));
  std::size_t feasible = 0;
  for (const SweepPoint& p : result.points) feasible += p.result.evaluation.feasible ? 1 : 0;
  o += fmt::format("<p>{} of {} points feasible; dwell {} s, ambient {} degC; {}.</p>\n", feasible,
                   result.points.size(), rq.base.dwell_s, rq.base.world.thermal.ambient_C,
                   rq.speeds_dps.empty() ? "recommended set per point"
                                         : fmt::format("given acceleration {} %, jerk {} %", rq.accel_pct, rq.jerk_pct));
  // Every point's verdict (issue 29), from the figures its CSV row carries.
  std::vector<std::pair<std::string, report_parts::VerdictInput>> verdicts;
  for (const SweepPoint& pt : result.points) {
    const Evaluation& e = pt.result.evaluation;
    verdicts.push_back({fmt::format("{} deg, {} g cm^2, {:.1f} V, {:.1f} deg/s", pt.angle_deg, pt.load_gcm2, pt.voltage_V, e.set.tidy.speed_dps),
                        {&e, e.feasible, e.binding_limit, rq.base.thermal_margin_K, rq.base.world.thermal.ambient_C, e.set.tidy.speed_dps, e.load_gcm2, nullptr}});
  }
  o += "<h2>Verdict per point</h2>\n" + report_parts::verdict_table(verdicts, 200);
  const std::vector<SweepGroup> groups = sweep_groups(result);
  std::vector<double> angles;
  for (const SweepPoint& p : result.points) {
    if (std::find(angles.begin(), angles.end(), p.angle_deg) == angles.end()) angles.push_back(p.angle_deg);
  }
  int plot_id = 0;
  for (const SweepGroup& g : groups) {
    const std::string label = fmt::format("{:.1f} V{}", g.voltage_V,
                                          g.speed_dps ? fmt::format(", {} deg/s", *g.speed_dps) : std::string(", recommended"));
    o += fmt::format("<h2>{}</h2>\n", xml_escape(label));
    svg::Plot p;
    p.id = fmt::format("positioning{}", plot_id);
    p.title = "Positioning time vs load (feasible points)";
    p.x = {"load", "g cm^2", {}, {}};
    p.y = {"positioning time", "s", 0.0, {}};
    for (std::size_t a = 0; a < angles.size(); ++a) {
      svg::Series s;
      s.label = fmt::format("{} deg", angles[a]);
      s.color = colour(a);
      for (const SweepPoint& pt : result.points) {
        if (pt.angle_deg != angles[a] || pt.voltage_V != g.voltage_V || pt.speed_dps != g.speed_dps) continue;
        if (!pt.result.evaluation.feasible) continue;
        s.x.push_back(pt.load_gcm2);
        s.y.push_back(pt.result.evaluation.positioning_s);
      }
      if (!s.x.empty()) p.series.push_back(std::move(s));
    }
    o += svg::to_svg(p) + "\n";

    const std::vector<HeaviestLoad> inv = heaviest_loads(result, g, targets);
    svg::Plot q;
    q.id = fmt::format("heaviest{}", plot_id++);
    q.title = "Heaviest load on the grid meeting a positioning time";
    q.x = {"target positioning time", "s", {}, {}};
    q.y = {"heaviest load", "g cm^2", 0.0, {}};
    for (std::size_t a = 0; a < angles.size(); ++a) {
      svg::Series s;
      s.label = fmt::format("{} deg", angles[a]);
      s.color = colour(a);
      // A step function: the heaviest load holds until the next target.
      for (const HeaviestLoad& h : inv) {
        if (h.angle_deg != angles[a] || !h.load_gcm2) continue;
        if (!s.y.empty()) {
          s.x.push_back(h.target_s);
          s.y.push_back(s.y.back());
        }
        s.x.push_back(h.target_s);
        s.y.push_back(*h.load_gcm2);
      }
      if (!s.x.empty()) q.series.push_back(std::move(s));
    }
    o += svg::to_svg(q) + "\n";
    o += "<table>\n<tr><th>angle deg</th>";
    for (double t : targets) o += fmt::format("<th>&le; {} s</th>", t);
    o += "</tr>\n";
    for (double angle : angles) {
      o += fmt::format("<tr><td>{}</td>", angle);
      for (const HeaviestLoad& h : inv) {
        if (h.angle_deg != angle) continue;
        o += h.load_gcm2 ? fmt::format("<td>{}</td>", *h.load_gcm2) : std::string("<td>-</td>");
      }
      o += "</tr>\n";
    }
    o += "</table>\n<p class=\"note\">Cells: the heaviest grid load (g cm^2) whose positioning time meets the "
         "target; '-': none on the grid.</p>\n";
  }
  o += io::html_page_close();
  return o;
}

std::filesystem::path write_sweep_report(const std::filesystem::path& dir, const SweepRequest& rq,
                                         const SweepResult& result, const std::vector<double>& targets) {
  return write_index(dir, sweep_report_html(rq, result, targets));
}

#else  // built without renders

bool reports_available() { return false; }
namespace {
[[noreturn]] void no_reports() { throw std::runtime_error("this build has no reports (SREH_WITH_RENDER=OFF)"); }
} // namespace
std::string size_report_html(const SizingRequest&, const SizingResult&, const UncertaintyResult*, const SettlingSpread*) {
  no_reports();
}
std::filesystem::path write_size_report(const std::filesystem::path&, const SizingRequest&, const SizingResult&,
                                        const UncertaintyResult*, const SettlingSpread*) {
  no_reports();
}
std::string sweep_report_html(const SweepRequest&, const SweepResult&, const std::vector<double>&) { no_reports(); }
std::filesystem::path write_sweep_report(const std::filesystem::path&, const SweepRequest&, const SweepResult&,
                                         const std::vector<double>&) { no_reports(); }

#endif

} // namespace sreh::sizing
