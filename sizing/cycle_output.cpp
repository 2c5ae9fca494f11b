// What `sreh-twin size --cycle` prints: the JSON object (docs/sizing.md
// "Cycles") or a readable summary with the ISDU writes of every set.
#include <cmath>

#include <fmt/format.h>

#include "sizing/cycle_output.hpp"
#include "sizing/output.hpp"

namespace sreh::sizing {
namespace {

double ns_rounded(double v) { return std::isfinite(v) ? std::round(v * 1e9) / 1e9 : v; }
nlohmann::json optional_number(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); }
nlohmann::json time_if(bool ok, double v) { return ok ? nlohmann::json(ns_rounded(v)) : nlohmann::json(); }

std::string duration_text(const std::optional<double>& s) {
  if (!s) return "never";
  if (*s < 120) return fmt::format("{:.0f} s", *s);
  if (*s < 7200) return fmt::format("{:.1f} min", *s / 60);
  return fmt::format("{:.1f} h", *s / 3600);
}

} // namespace

std::vector<IsduWrite> all_writes(const CycleEvaluation& e) {
  std::vector<IsduWrite> out;
  for (const ParameterSetValues& s : e.sets) {
    for (const IsduWrite& w : s.writes) {
      const bool seen = std::any_of(out.begin(), out.end(), [&](const IsduWrite& o) {
        return o.index == w.index && o.subindex == w.subindex; // index 85 once, whatever the number of sets
      });
      if (!seen) out.push_back(w);
    }
  }
  return out;
}

nlohmann::json cycle_to_json(const CycleRequest& rq, const CycleResult& r) {
  const CycleEvaluation& e = r.evaluation;
  nlohmann::json j;
  j["mode"] = r.recommended ? "recommend" : "evaluate";
  j["request"] = {{"cycle_file", rq.file},
                  {"voltage_V", rq.voltage_V},
                  {"source_resistance_ohm", rq.source_resistance_ohm},
                  {"bus_capacitance_F", rq.bus_capacitance_F},
                  {"ambient_C", rq.ambient_C},
                  {"mounting_tilt_deg", rq.mounting_tilt_deg},
                  {"process_torque_Nm", rq.process_torque_Nm},
                  {"tolerance_deg", rq.tolerance_deg},
                  {"wait_ms", rq.wait_ms},
                  {"thermal_margin_K", rq.thermal_margin_K},
                  {"handshake_cycles", rq.handshake_cycles},
                  {"cycles", rq.cycles}};
  nlohmann::json segs = nlohmann::json::array();
  for (const SegmentResult& s : e.segments) {
    nlohmann::json o = {{"kind", s.kind}, {"duration_s", ns_rounded(s.duration_s)}};
    if (s.kind == "move") {
      o["parameter_set"] = s.parameter_set;
      o["start_deg"] = s.start_deg;
      o["target_deg"] = s.target_deg;
      o["load_gcm2"] = s.load_gcm2;
      o["process_torque_Nm"] = s.process_torque_Nm;
      o["travel_s"] = ns_rounded(s.travel_s);
      o["settling_s"] = time_if(s.completed, s.settling_s);
      o["positioning_s"] = time_if(s.completed, s.positioning_s);
      o["peak_torque_Nm"] = s.peak_torque_Nm;
      o["rms_torque_Nm"] = s.rms_torque_Nm;
      o["max_tracking_error_deg"] = s.max_tracking_error_deg;
      o["completed"] = s.completed;
      if (!s.completed) o["duration_s"] = nullptr;
    } else if (s.kind == "dwell") {
      o["process_torque_Nm"] = s.process_torque_Nm;
      o["hold_rms_torque_Nm"] = s.hold_rms_torque_Nm;
    }
    segs.push_back(o);
  }
  j["segments"] = segs;
  j["completed"] = e.completed;
  j["cycle_s"] = time_if(e.completed, e.cycle_s);
  j["cycles_per_min"] = time_if(e.completed, e.cycles_per_min);
  j["handshake_s"] = e.handshake_s;
  j["peak_torque_Nm"] = e.peak_torque_Nm;
  j["rms_torque_Nm"] = e.rms_torque_Nm;
  j["torque_capability_Nm"] = e.torque_capability_Nm;
  j["continuous_torque_Nm"] = e.continuous_torque_Nm;
  j["max_tracking_error_deg"] = e.max_tracking_error_deg;
  j["tracking_limit_deg"] = e.tracking_limit_deg;
  j["mean_loss_W"] = e.mean_loss_W;
  j["steady_temperature_C"] = e.steady_temperature_C;
  j["time_to_warning_s"] = optional_number(e.time_to_warning_s);
  j["time_to_trip_s"] = optional_number(e.time_to_trip_s);
  j["utilisation"] = {{"peak_torque_pct", e.utilisation.peak_torque_pct},
                      {"rms_torque_pct", e.utilisation.rms_torque_pct},
                      {"thermal_margin_K", e.utilisation.thermal_margin_K},
                      {"required_thermal_margin_K", rq.thermal_margin_K}};
  j["supply"] = {{"peak_current_A", e.supply.peak_current_A},
                 {"rms_current_A", e.supply.rms_current_A},
                 {"regen_energy_J", e.supply.regen_energy_J},
                 {"peak_bus_V", e.supply.peak_bus_V},
                 {"bus_max_V", e.supply.bus_max_V},
                 {"overvoltage_advice", e.supply.overvoltage_advice}};
  j["binding_limit"] = e.binding_limit;
  j["feasible"] = e.feasible;
  j["reason"] = e.reason;
  j["simulations"] = r.simulations;
  j["backoffs"] = r.backoffs;
  nlohmann::json sets = nlohmann::json::array();
  for (const ParameterSetValues& s : e.sets) {
    nlohmann::json writes = nlohmann::json::array();
    for (const IsduWrite& w : s.writes) {
      writes.push_back({{"index", w.index}, {"subindex", w.subindex}, {"value", w.value}, {"comment", w.comment}});
    }
    sets.push_back({{"parameter_set", s.set},
                    {"speed_dps", s.tidy.speed_dps},
                    {"accel_pct", s.tidy.accel_pct},
                    {"jerk_pct", s.tidy.jerk_pct},
                    {"load_gcm2", s.load_gcm2},
                    {"tolerance_deg", s.tolerance_deg},
                    {"wait_ms", s.wait_ms},
                    {"timeout_ms", s.timeout_ms},
                    {"isdu_writes", writes}});
  }
  j["sets"] = sets;
  return j;
}

std::string cycle_summary_text(const CycleRequest& rq, const CycleResult& r) {
  const CycleEvaluation& e = r.evaluation;
  std::string s;
  s += fmt::format("Cycle {}: {} segments, {:.1f} V, ambient {} degC, mounting tilt {} deg, {} repetitions simulated\n",
                   rq.file, rq.segments.size(), rq.voltage_V, rq.ambient_C, rq.mounting_tilt_deg, rq.cycles);
  s += r.recommended ? fmt::format("Recommended sets ({} simulations{}):\n", r.simulations,
                                   r.backoffs ? fmt::format(", slowed down {} times for the whole cycle", r.backoffs) : "")
                     : std::string("Given sets:\n");
  for (const ParameterSetValues& p : e.sets) {
    s += fmt::format("  set {}: speed {:.1f} deg/s, acceleration {:.1f} %, jerk {:.1f} %, load {:.0f} g cm^2\n", p.set,
                     p.tidy.speed_dps, p.tidy.accel_pct, p.tidy.jerk_pct, p.load_gcm2);
  }
  s += "  #   kind   from -> to deg       load g cm^2  set  travel s  settle s  positioning s  duration s  peak / rms N m\n";
  for (std::size_t i = 0; i < e.segments.size(); ++i) {
    const SegmentResult& g = e.segments[i];
    auto t = [&](double v) { return g.completed ? fmt::format("{:.4f}", v) : std::string("-"); };
    if (g.kind == "move") {
      s += fmt::format("  {:<3} move   {:>8.2f} -> {:<8.2f}  {:>11.0f}  {:>3}  {:>8.4f}  {:>8}  {:>13}  {:>10}  {:.3f} / {:.3f}\n",
                       i + 1, g.start_deg, g.target_deg, g.load_gcm2, g.parameter_set, g.travel_s, t(g.settling_s),
                       t(g.positioning_s), t(g.duration_s), g.peak_torque_Nm, g.rms_torque_Nm);
    } else if (g.kind == "dwell") {
      s += fmt::format("  {:<3} dwell  holding torque {:+.3f} N m {:>47}  {:>10.4f}  {:.3f} rms\n", i + 1,
                       g.process_torque_Nm, "", g.duration_s, g.hold_rms_torque_Nm);
    } else {
      s += fmt::format("  {:<3} load   load change (grip / release) {:>44}  {:>10.4f}\n", i + 1, "", 0.0);
    }
  }
  s += fmt::format("  cycle             {}   (moves incl. {} ms handshake each + dwells){}\n",
                   e.completed ? fmt::format("{:8.4f} s", e.cycle_s) : std::string("       - s"), e.handshake_s * 1e3,
                   e.completed ? fmt::format(": {:.1f} cycles/min", e.cycles_per_min) : "");
  s += fmt::format("  torque peak / rms {:8.3f} / {:.3f} N m of {:.3f} N m\n", e.peak_torque_Nm, e.rms_torque_Nm,
                   e.torque_capability_Nm);
  s += fmt::format("  tracking error    {:8.3f} deg (limit {:.1f} deg, index 87.1)\n", e.max_tracking_error_deg,
                   e.tracking_limit_deg);
  s += fmt::format("  temperature       {:8.1f} degC steady ({:.2f} W), 70 degC warning: {}, 75 degC trip: {}\n",
                   e.steady_temperature_C, e.mean_loss_W, duration_text(e.time_to_warning_s),
                   duration_text(e.time_to_trip_s));
  s += fmt::format("  utilisation       peak torque {:.0f} % at speed, RMS {:.0f} % of continuous {:.3f} N m, "
                   "thermal margin {:.1f} K (required {:.1f} K)\n",
                   e.utilisation.peak_torque_pct, e.utilisation.rms_torque_pct, e.continuous_torque_Nm,
                   e.utilisation.thermal_margin_K, rq.thermal_margin_K);
  s += fmt::format("  supply            peak {:.2f} A, RMS {:.2f} A, regenerated {:.3f} J per braking, bus peak {:.2f} V "
                   "(window max {:.1f} V){}\n",
                   e.supply.peak_current_A, e.supply.rms_current_A, e.supply.regen_energy_J, e.supply.peak_bus_V,
                   e.supply.bus_max_V,
                   e.supply.overvoltage_advice ? ": manual 7.2 114.4 applies, add capacity or a chopper" : "");
  s += fmt::format("  binding limit     {}\n", e.binding_limit);
  s += fmt::format("  feasible          {}{}\n", e.feasible ? "yes" : "NO", e.feasible ? "" : ": " + e.reason);
  s += "ISDU writes of every set, as scenario steps:\n";
  for (const IsduWrite& w : all_writes(e)) s += "  " + isdu_write_line(w) + "\n";
  return s;
}

} // namespace sreh::sizing
