// What `sreh-twin size --cycle` prints: the JSON object (docs/sizing.md
// "Cycles") or a readable summary with the ISDU writes of every set.
#include <algorithm>

#include <fmt/format.h>

#include "sizing/cycle_output.hpp"

#include "sizing/uncertainty.hpp"
#include "sizing/output.hpp"

namespace sreh::sizing {

namespace {

// One listed segment of the last repetition; a move's times are null when
// it did not complete.
nlohmann::json segment_json(const SegmentResult& s) {
  if (s.kind == "move") {
    return {{"kind", s.kind},
            {"duration_s", time_if(s.completed, s.duration_s)},
            {"parameter_set", s.parameter_set},
            {"start_deg", s.start_deg},
            {"target_deg", s.target_deg},
            {"load_gcm2", s.load_gcm2},
            {"process_torque_Nm", s.process_torque_Nm},
            {"travel_s", ns_rounded(s.travel_s)},
            {"settling_s", time_if(s.completed, s.settling_s)},
            {"positioning_s", time_if(s.completed, s.positioning_s)},
            {"peak_torque_Nm", s.peak_torque_Nm},
            {"rms_torque_Nm", s.rms_torque_Nm},
            {"max_tracking_error_deg", s.max_tracking_error_deg},
            {"completed", s.completed}};
  }
  nlohmann::json o = {{"kind", s.kind}, {"duration_s", ns_rounded(s.duration_s)}};
  if (s.kind == "dwell") {
    o["process_torque_Nm"] = s.process_torque_Nm;
    o["hold_rms_torque_Nm"] = s.hold_rms_torque_Nm;
  }
  return o;
}

} // namespace

nlohmann::json cycle_to_json(const CycleRequest& rq, const CycleResult& r, const UncertaintyResult* u) {
  const CycleEvaluation& e = r.evaluation;
  nlohmann::json j;
  j["mode"] = r.recommended ? "recommend" : "evaluate";
  j["request"] = {{"cycle_file", rq.file},
                  {"voltage_V", rq.world.supply.voltage_V},
                  {"source_resistance_ohm", rq.world.supply.source_resistance_ohm},
                  {"bus_capacitance_F", rq.world.supply.bus_capacitance_F},
                  {"ambient_C", rq.world.thermal.ambient_C},
                  {"mounting_tilt_deg", rq.world.mounting_tilt_deg},
                  {"process_torque_Nm", rq.process_torque_Nm},
                  {"tolerance_deg", rq.settling.tolerance_deg},
                  {"wait_ms", rq.settling.wait_ms},
                  {"thermal_margin_K", rq.thermal_margin_K},
                  {"handshake_cycles", rq.handshake_cycles},
                  {"cycles", rq.cycles}};
  nlohmann::json segs = nlohmann::json::array();
  for (const SegmentResult& s : e.segments) segs.push_back(segment_json(s));
  j["segments"] = segs;
  j["completed"] = e.completed;
  j["cycle_s"] = time_if(e.completed, e.cycle_s);
  j["cycles_per_min"] = time_if(e.completed, e.cycles_per_min);
  j["handshake_s"] = e.handshake_s;
  put_figures_json(j, e, rq.thermal_margin_K);
  j["binding_limit"] = e.binding_limit;
  j["feasible"] = u ? u->feasible_worst_case : e.feasible;
  if (u) j["feasible_nominal"] = e.feasible;
  j["simulations"] = r.simulations;
  j["backoffs"] = r.backoffs;
  nlohmann::json sets = nlohmann::json::array();
  for (const ParameterSetValues& s : e.sets) sets.push_back(json_parameter_set(s));
  j["sets"] = sets;
  if (u) add_uncertainty_json(j, *u);
  return j;
}

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

std::string cycle_summary_text(const CycleRequest& rq, const CycleResult& r, const UncertaintyResult* u) {
  const CycleEvaluation& e = r.evaluation;
  std::string s;
  s += fmt::format("Cycle {}: {} segments, {:.1f} V, ambient {} degC, mounting tilt {} deg, {} repetitions simulated\n",
                   rq.file, rq.segments.size(), rq.world.supply.voltage_V, rq.world.thermal.ambient_C, rq.world.mounting_tilt_deg, rq.cycles);
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
  s += tracking_text(e);
  s += fmt::format("  temperature       {:8.1f} degC steady ({:.2f} W), 70 degC warning: {}, 75 degC trip: {}\n",
                   e.steady_temperature_C, e.mean_loss_W, duration_text(e.time_to_warning_s),
                   duration_text(e.time_to_trip_s));
  s += verdict_text(e, rq.thermal_margin_K, e.binding_limit, e.feasible, u);
  if (u) s += uncertainty_text(*u);
  s += "ISDU writes of every set, as scenario steps:\n";
  for (const IsduWrite& w : all_writes(e)) s += "  " + isdu_write_line(w) + "\n";
  return s;
}

} // namespace sreh::sizing
