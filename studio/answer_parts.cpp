#include "studio/answer_parts.hpp"

#include <cmath>

#include <fmt/format.h>

#include "renders/figure.hpp"
#include "sizing/output.hpp"
#include "sizing/report.hpp"
#include "sizing/report_parts.hpp"
#include "sizing/uncertainty.hpp"
#include "studio/answer.hpp"

namespace sreh::studio {
namespace {

using sizing::Evaluation;

// The trace as the report's speed-torque plane shows it: the motor's
// capability at the supply and the samples, motoring and braking.
std::string speed_torque_svg(const sizing::SizingRequest& rq, const Evaluation& e) {
  namespace rp = sizing::report_parts;
  svg::Plot p = rp::speed_torque_plane("studio-speed-torque",
                                       fmt::format("Speed-torque at {:.1f} V", rq.world.supply.voltage_V));
  svg::Series motoring{"motoring", {}, {}, "#1f77b4", 1.0, false, true};
  svg::Series braking{"braking", {}, {}, "#ff7f0e", 1.0, false, true};
  for (const TraceRow& r : e.trace) {
    svg::Series& s = r.torque_Nm * r.velocity_dps < 0 ? braking : motoring;
    s.x.push_back(std::abs(r.velocity_dps));
    s.y.push_back(std::abs(r.torque_Nm));
  }
  p.series = {rp::motor_envelope(rq.world.module.drive.motor, rq.world.supply.voltage_V, 1.05, "capability (motoring)",
                                 "#d62728", 1.6, false),
              motoring, braking};
  p.vlines = {{e.set.setting.speed_dps, "set speed", "#555555"}};
  return report::figure(p, false);
}

std::string plots_html(const sizing::SizingRequest& rq, const Evaluation& e) {
  std::string o;
  if (!e.trace.empty()) {
    o += report::figure(sizing::report_parts::position_plot("studio-position", e.trace), false);
    o += speed_torque_svg(rq, e);
  }
  o += sizing::temperature_plot(e.mean_loss_W, rq.world.thermal.ambient_C, rq.thermal_margin_K, e.time_to_trip_s,
                                rq.world.module.thermal);
  return o;
}

// One row of "how far over each limit": the value, what is allowed, by how much over.
Json limit_row(const std::string& limit, const std::string& value, const std::string& allowed, double over,
               const std::string& unit) {
  return {{"limit", limit_in_words(limit)}, {"value", value}, {"allowed", allowed}, {"over", over > 0},
          {"by", over > 0 ? fmt::format("over by {:.1f} {}", over, unit) : std::string("within")}};
}

Json limits_table(const sizing::SizingRequest& rq, const Evaluation& e) {
  Json rows = figure_limits(e, rq.thermal_margin_K);
  if (rq.max_positioning_ms) {
    rows.push_back(limit_row("max_positioning", e.completed ? fmt::format("{:.1f} ms", e.positioning_s * 1e3) : "not completed",
                             fmt::format("{:.1f} ms", *rq.max_positioning_ms),
                             e.completed ? e.positioning_s * 1e3 - *rq.max_positioning_ms : 0.0, "ms"));
  }
  if (rq.max_cycle_ms) {
    rows.push_back(limit_row("max_cycle", e.completed ? fmt::format("{:.1f} ms", e.cycle_s * 1e3) : "not completed",
                             fmt::format("{:.1f} ms", *rq.max_cycle_ms), e.completed ? e.cycle_s * 1e3 - *rq.max_cycle_ms : 0.0,
                             "ms"));
  }
  return rows;
}

// Options near the state that may be feasible, each as the change to the
// state, in the order the page offers them (the first feasible is "nearest").
std::vector<std::pair<std::string, Json>> alternatives(const Json& s, const sizing::SizingResult& r) {
  std::vector<std::pair<std::string, Json>> alts;
  const bool target = s["target"] != "none";
  if (!s["set"].is_null()) alts.push_back({"a recommended set instead of the given one", {{"set", nullptr}}});
  if (target) alts.push_back({"the fastest feasible set, without the required time", {{"target", "none"}, {"set", nullptr}}});
  if (s["voltage_V"].get<double>() < sizing::max_voltage_V()) {
    alts.push_back({fmt::format("the same at {:.0f} V", sizing::max_voltage_V()), {{"voltage_V", sizing::max_voltage_V()}}});
  }
  if (r.binding_limit == "temperature" || r.evaluation.binding_limit == "temperature") {
    alts.push_back({"a longer dwell (+0.5 s) to cool", {{"dwell_s", s["dwell_s"].get<double>() + 0.5}}});
  }
  return alts;
}

Json way_out(const Json& s, const sizing::SizingRequest& rq, const sizing::SizingResult& r) {
  Json w = {{"limits", limits_table(rq, r.evaluation)}, {"options", Json::array()}};
  for (const auto& [label, patch] : alternatives(s, r)) {
    Json patched = s;
    for (auto it = patch.begin(); it != patch.end(); ++it) patched[it.key()] = it.value();
    sizing::SizingRequest alt = sizing_request(patched);
    alt.keep_trace = false;
    const sizing::SizingResult ar = sizing::size(alt);
    const Evaluation& e = ar.evaluation;
    w["options"].push_back({{"label", label},
                            {"patch", patch},
                            {"feasible", ar.feasible},
                            {"binding_limit", limit_in_words(ar.binding_limit)},
                            {"positioning_s", e.completed ? Json(sizing::ns_rounded(e.positioning_s)) : Json()},
                            {"cycle_s", e.completed ? Json(sizing::ns_rounded(e.cycle_s)) : Json()},
                            {"set", set_json(e.set)}});
  }
  return w;
}

} // namespace

Json set_json(const sizing::ParameterSetValues& s) {
  return {{"parameter_set", s.set}, {"speed_dps", s.tidy.speed_dps}, {"accel_pct", s.tidy.accel_pct}, {"jerk_pct", s.tidy.jerk_pct}};
}

Json figure_limits(const sizing::TraceFigures& e, double required_margin_K) {
  const sizing::Utilisation& u = e.utilisation;
  Json rows = Json::array();
  rows.push_back(limit_row("torque_at_speed", fmt::format("{:.0f} %", u.peak_torque_pct),
                           fmt::format("{:.0f} %", 100 * sizing::kTorqueMargin),
                           u.peak_torque_pct - 100 * sizing::kTorqueMargin, "% of the capability"));
  rows.push_back(limit_row("rms_torque", fmt::format("{:.0f} %", u.rms_torque_pct), "100 %", u.rms_torque_pct - 100,
                           "% of the continuous torque"));
  rows.push_back(limit_row("temperature", fmt::format("margin {:.1f} K", u.thermal_margin_K),
                           fmt::format("margin {:.1f} K", required_margin_K), required_margin_K - u.thermal_margin_K, "K"));
  const double track_allowed = sizing::kTrackingMargin * e.tracking_limit_deg;
  rows.push_back(limit_row("tracking", fmt::format("{:.3f} deg", e.max_tracking_error_deg), fmt::format("{:.3f} deg", track_allowed),
                           e.tracking_limit_deg > 0 ? e.max_tracking_error_deg - track_allowed : 0.0, "deg"));
  return rows;
}

void add_answer_parts(Json& out, const Json& s, const sizing::SizingRequest& rq, const sizing::SizingResult& r,
                      const sizing::UncertaintyResult* u) {
  const Evaluation& e = r.evaluation;
  // With the uncertainty switch the answer is the verdict over every sample (A-SIZE-UNC-2), as size --uncertainty's.
  const bool feasible = u ? u->feasible_worst_case : r.feasible;
  out["verdict_html"] = sizing::report_parts::verdict_block(
      {&e, r.feasible, r.binding_limit, rq.thermal_margin_K, rq.world.thermal.ambient_C, e.set.setting.speed_dps, e.load_gcm2, u});
  if (u) {
    out["uncertainty_html"] = sizing::report_parts::uncertainty_section(
        *u, {e.positioning_s, e.settling_s, e.peak_torque_Nm, e.steady_temperature_C, std::nullopt});
  }
  out["plots_html"] = plots_html(rq, e);
  out["summary"] = {{"feasible", feasible},
                    {"binding_limit", r.binding_limit},
                    {"binding_limit_words", limit_in_words(r.binding_limit)},
                    {"reason", e.reason},
                    {"set", set_json(e.set)},
                    {"sets", Json::array({set_json(e.set)})}};
  // Writes to paste only for a set that meets everything asked (issue 37).
  out["writes_ready"] = feasible;
  out["writes"] = Json::array();
  if (feasible) {
    for (const sizing::IsduWrite& w : e.set.writes) out["writes"].push_back(sizing::isdu_write_line(w));
  } else if (u) { // the options near it would need the samples too: the limits only
    out["way_out"] = {{"limits", limits_table(rq, e)}, {"options", Json::array()}};
  } else {
    out["way_out"] = way_out(s, rq, r);
  }
}

} // namespace sreh::studio
