#include "sizing/output.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "twin/load_figures.hpp"
#include "sizing/limit_names.hpp"
#include "sizing/settling_spread.hpp"
#include "sizing/uncertainty.hpp"

namespace sreh::sizing {
namespace {

std::string time_text(bool completed, double v, const char* unit) {
  return completed ? fmt::format("{:8.4f} {}", v, unit) : fmt::format("{:>8} {}", "-", unit);
}

} // namespace

double ns_rounded(double v) { return std::isfinite(v) ? std::round(v * 1e9) / 1e9 : v; }
nlohmann::json optional_number(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); }
nlohmann::json time_if(bool completed, double v) { return completed ? nlohmann::json(ns_rounded(v)) : nlohmann::json(); }

std::string duration_text(const std::optional<double>& s) {
  if (!s) return "never";
  if (*s < 120) return fmt::format("{:.0f} s", *s);
  if (*s < 7200) return fmt::format("{:.1f} min", *s / 60);
  return fmt::format("{:.1f} h", *s / 3600);
}

nlohmann::json json_utilisation(const Utilisation& u, double required_thermal_margin_K) {
  return {{"peak_torque_pct", u.peak_torque_pct},
          {"rms_torque_pct", u.rms_torque_pct},
          {"thermal_margin_K", u.thermal_margin_K},
          {"required_thermal_margin_K", required_thermal_margin_K}};
}

nlohmann::json json_supply(const SupplyFigures& s) {
  return {{"peak_current_A", s.peak_current_A}, {"rms_current_A", s.rms_current_A},
          {"regen_energy_J", s.regen_energy_J}, {"peak_bus_V", s.peak_bus_V},
          {"bus_max_V", s.bus_max_V},           {"overvoltage_advice", s.overvoltage_advice}};
}

void put_figures_json(nlohmann::json& j, const TraceFigures& f, double required_thermal_margin_K) {
  j["peak_torque_Nm"] = f.peak_torque_Nm;
  j["rms_torque_Nm"] = f.rms_torque_Nm;
  j["torque_capability_Nm"] = f.torque_capability_Nm;
  j["continuous_torque_Nm"] = f.continuous_torque_Nm;
  j["max_tracking_error_deg"] = f.max_tracking_error_deg;
  j["tracking_limit_deg"] = f.tracking_limit_deg;
  j["mean_loss_W"] = f.mean_loss_W;
  j["steady_temperature_C"] = f.steady_temperature_C;
  j["time_to_warning_s"] = optional_number(f.time_to_warning_s);
  j["time_to_trip_s"] = optional_number(f.time_to_trip_s);
  j["utilisation"] = json_utilisation(f.utilisation, required_thermal_margin_K);
  j["supply"] = json_supply(f.supply);
  j["reason"] = f.reason;
}

nlohmann::json json_parameter_set(const ParameterSetValues& s) {
  nlohmann::json writes = nlohmann::json::array();
  for (const IsduWrite& w : s.writes) {
    writes.push_back({{"index", w.index}, {"subindex", w.subindex}, {"value", w.value}, {"comment", w.comment}});
  }
  return {{"parameter_set", s.set},      {"speed_dps", s.tidy.speed_dps}, {"accel_pct", s.tidy.accel_pct},
          {"jerk_pct", s.tidy.jerk_pct}, {"load_gcm2", s.load_gcm2},      {"tolerance_deg", s.tolerance_deg},
          {"wait_ms", s.wait_ms},        {"timeout_ms", s.timeout_ms},    {"isdu_writes", writes}};
}

std::string tracking_text(const TraceFigures& f) {
  return fmt::format("  tracking error    {:8.3f} deg (limit {:.1f} deg, index 87.1)\n", f.max_tracking_error_deg,
                     f.tracking_limit_deg);
}

std::string supply_text(const SupplyFigures& s) {
  return fmt::format("peak {:.2f} A, RMS {:.2f} A, regenerated {:.3f} J per braking, bus peak {:.2f} V (window max {:.1f} V){}",
                     s.peak_current_A, s.rms_current_A, s.regen_energy_J, s.peak_bus_V, s.bus_max_V,
                     s.overvoltage_advice ? ": manual 7.2 114.4 applies, add capacity or a chopper" : "");
}

std::string verdict_text(const TraceFigures& f, double required_thermal_margin_K, const std::string& binding_limit,
                         bool feasible, const UncertaintyResult* u) {
  std::string s;
  s += fmt::format("  utilisation       peak torque {:.0f} % at speed, RMS {:.0f} % of continuous {:.3f} N m, "
                   "thermal margin {:.1f} K (required {:.1f} K)\n",
                   f.utilisation.peak_torque_pct, f.utilisation.rms_torque_pct, f.continuous_torque_Nm,
                   f.utilisation.thermal_margin_K, required_thermal_margin_K);
  s += "  supply            " + supply_text(f.supply) + "\n";
  s += fmt::format("  binding limit     {}\n", limit_in_words(binding_limit));
  if (u) { // one verdict (issue 35): over the nominal and every sample
    s += fmt::format("  feasible          {}: {}{}\n", u->feasible_worst_case ? "yes, in every sample" : "NO",
                     u->verdict.sentence(), f.feasible ? "" : "; on the nominal model: " + f.reason);
  } else {
    s += fmt::format("  feasible          {}{}\n", feasible ? "yes" : "NO", feasible ? "" : ": " + f.reason);
  }
  return s;
}

std::string isdu_write_line(const IsduWrite& w) {
  // A scenario step, ready to paste under `steps:` (or, without "- ", under device: isdu:).
  return fmt::format("- isdu_write: {{index: {}, subindex: {}, value: {}}}  # {}", w.index, w.subindex, w.value,
                     w.comment);
}

namespace {
// The mounting and the gravity torque it gives the load (issue 39: the
// answer depends on it, so the summary says it).
std::string mounting_words(double tilt_deg) {
  if (tilt_deg == 0) return "vertical axis";
  if (tilt_deg == 90) return "horizontal axis (tilt 90 deg)";
  return fmt::format("axis tilted {:g} deg from vertical", tilt_deg);
}

double gravity_torque_Nm(const SizingRequest& rq) {
  if (std::sin(rq.world.mounting_tilt_deg * std::numbers::pi / 180.0) == 0) return 0;
  try {
    return gravity_torque_max_Nm(load_figures(rq.world.load), rq.world.mounting_tilt_deg);
  } catch (const std::invalid_argument&) {
    return 0; // a load the twin rejects has failed the run before this
  }
}

std::string mounting_text(const SizingRequest& rq) {
  const double g = gravity_torque_Nm(rq);
  return fmt::format("Mounting: {}; gravity torque on the load {}\n", mounting_words(rq.world.mounting_tilt_deg),
                     g > 0 ? fmt::format("up to {:.3f} N m", g) : std::string("none (centre of mass on the axis or axis vertical)"));
}
} // namespace

nlohmann::json to_json(const SizingRequest& rq, const SizingResult& r, const AnswerExtras& x) {

  const Evaluation& e = r.evaluation;
  nlohmann::json j;
  j["mode"] = r.recommended ? "recommend" : "evaluate";
  j["request"] = {{"angle_deg", rq.angle_deg},   {"load_gcm2", e.load_gcm2},       {"voltage_V", rq.world.supply.voltage_V},
                  {"dwell_s", rq.dwell_s},       {"tolerance_deg", rq.settling.tolerance_deg}, {"wait_ms", rq.settling.wait_ms},
                  {"ambient_C", rq.world.thermal.ambient_C},   {"parameter_set", rq.parameter_set}, {"cycles", rq.cycles},
                  {"thermal_margin_K", rq.thermal_margin_K},
                  {"mounting_tilt_deg", rq.world.mounting_tilt_deg},
                  {"load_name", rq.load_name},
                  {"handshake_cycles", rq.handshake_cycles},
                  {"max_positioning_ms", optional_number(rq.max_positioning_ms)},
                  {"max_cycle_ms", optional_number(rq.max_cycle_ms)}};
  j["gravity_torque_max_Nm"] = gravity_torque_Nm(rq);
  j["travel_s"] = ns_rounded(e.travel_s);
  j["completed"] = e.completed;
  j["settling_s"] = time_if(e.completed, e.settling_s);
  j["positioning_s"] = time_if(e.completed, e.positioning_s);
  j["cycle_s"] = time_if(e.completed, e.cycle_s);
  j["cycles_per_min"] = time_if(e.completed, e.cycles_per_min);
  put_figures_json(j, e, rq.thermal_margin_K);
  j["min_torque_headroom"] = e.min_torque_headroom;
  // The answer (issue 17): for a search, whether the target (or, without
  // one, any set) is met with every margin; for a given set, its own check.
  // With --uncertainty: the verdict over every sample (A-SIZE-UNC-2).
  j["feasible"] = x.uncertainty ? x.uncertainty->feasible_worst_case : r.feasible;
  if (x.uncertainty) j["feasible_nominal"] = r.feasible;
  j["objective"] = r.objective.empty() ? "evaluate" : r.objective;
  j["binding_limit"] = r.binding_limit;
  j["best_positioning_s"] = time_if(r.best_positioning_s >= 0, r.best_positioning_s);
  j["best_cycle_s"] = time_if(r.best_cycle_s >= 0, r.best_cycle_s);
  j["candidates"] = r.candidates;
  j["handshake_s"] = e.handshake_s;
  j["simulations"] = r.simulations;
  j["recommended"] = json_parameter_set(e.set);
  nlohmann::json moves = nlohmann::json::array();
  for (const MoveResult& m : e.moves) {
    moves.push_back({{"target_deg", m.target_deg},
                     {"travel_s", ns_rounded(m.travel_s)},
                     {"settling_s", time_if(m.completed, m.settling_s)},
                     {"positioning_s", time_if(m.completed, m.positioning_s)},
                     {"max_tracking_error_deg", m.max_tracking_error_deg},
                     {"overshoot_deg", m.overshoot_deg},
                     {"in_window_s", m.in_window_s >= 0 ? nlohmann::json(m.in_window_s) : nlohmann::json()},
                     {"completed", m.completed}});
  }
  j["moves"] = moves;
  if (x.spread) j["settling_spread"] = settling_spread_json(*x.spread);
  if (x.uncertainty) add_uncertainty_json(j, *x.uncertainty);
  return j;
}

namespace {

// The answer's first line: what the set is.
std::string answer_label(const SizingResult& r, const UncertaintyResult* u) {
  if (!r.recommended) return "Given";
  if (u && u->robust.searched) {
    if (!u->robust.found) return "No set feasible in every sample; the nominal optimum:";
    return r.objective == "gentlest" ? "Gentlest set meeting the target in every sample:" : "Fastest set feasible in every sample:";
  }
  if (!r.feasible) return "Target not reachable; fastest feasible";
  return r.objective == "gentlest" ? "Gentlest set meeting the target:" : "Fastest feasible set:";
}

} // namespace

std::string summary_text(const SizingRequest& rq, const SizingResult& r, const AnswerExtras& x) {
  const Evaluation& e = r.evaluation;
  std::string s;
  s += fmt::format("Sizing: {} deg back and forth, load {:.1f} g cm^2{}, {:.1f} V, dwell {} s, ambient {} degC\n",
                   rq.angle_deg, e.load_gcm2, rq.load_name.empty() ? "" : " (" + rq.load_name + ")", rq.world.supply.voltage_V,
                   rq.dwell_s, rq.world.thermal.ambient_C);
  s += mounting_text(rq);
  s += fmt::format("{} parameter set {}: speed {:.1f} deg/s, acceleration {:.1f} %, jerk {:.1f} %\n",
                   answer_label(r, x.uncertainty), e.set.set, e.set.setting.speed_dps, e.set.setting.accel_pct, e.set.setting.jerk_pct);
  s += fmt::format("  travel time       {:8.4f} s   (planned S-curve, manual 3.5.2 (1))\n", e.travel_s);
  s += fmt::format("  settling time     {}   (incl. waiting time {:.1f} ms, simulated)\n",
                   time_text(e.completed, e.settling_s, "s"), e.set.wait_ms);
  s += fmt::format("  positioning time  {}   (worst of {} moves{})\n", time_text(e.completed, e.positioning_s, "s"),
                   e.moves.size(), e.completed ? "" : "; not all completed");
  if (x.spread) s += settling_spread_text(*x.spread);
  s += fmt::format("  cycle             {}   = 2 moves + 2 handshakes + 2 dwells{}\n", time_text(e.completed, e.cycle_s, "s"),
                   e.completed ? fmt::format(": {:.1f} cycles/min", e.cycles_per_min) : "");
  s += fmt::format("  torque peak / rms {:8.3f} / {:.3f} N m of {:.3f} N m ({:.0f} %)\n", e.peak_torque_Nm,
                   e.rms_torque_Nm, e.torque_capability_Nm,
                   e.torque_capability_Nm > 0 ? 100 * e.peak_torque_Nm / e.torque_capability_Nm : 0.0);
  s += tracking_text(e);
  s += fmt::format("  temperature       {:8.1f} degC steady under continuous cycling ({:.2f} W), 70 degC warning: {}, "
                   "75 degC trip: {}\n",
                   e.steady_temperature_C, e.mean_loss_W, duration_text(e.time_to_warning_s),
                   duration_text(e.time_to_trip_s));
  s += verdict_text(e, rq.thermal_margin_K, r.binding_limit, r.feasible, x.uncertainty);
  if (x.uncertainty) s += uncertainty_text(*x.uncertainty);
  s += fmt::format("ISDU writes, as scenario steps ({} simulation{}):\n", r.simulations, r.simulations == 1 ? "" : "s");
  for (const IsduWrite& w : e.set.writes) s += "  " + isdu_write_line(w) + "\n";
  return s;
}

} // namespace sreh::sizing
