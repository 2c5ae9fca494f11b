// evaluate_cycle: a multi-segment cycle in the twin, as a PLC runs it
// (interfaces.md: the device only sees process data and ISDU): every set
// written to 64+n over ISDU, Motor On, then the segments in order, the
// whole list `cycles` times (A-SIZE-17). Moves go through process data with
// their set; a dwell holds (with its holding torque); a load change swaps
// the load on the flange (Twin::set_load, A-TWIN-33). The figures are those
// of the last repetition, judged by the same checks as a single move.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "device_logic/planner.hpp"
#include "device_logic/units.hpp"
#include "sizing/cycle.hpp"
#include "sizing/run_parts.hpp"
#include "sizing/thermal_estimate.hpp"
#include "sizing/twin_factory.hpp"
#include "twin/thermal.hpp"

namespace sreh::sizing {
namespace {

// A SizingRequest carrying the cycle's set-wide values, for make_parameter_set.
SizingRequest set_request(const CycleRequest& rq, int set) {
  SizingRequest s;
  s.voltage_V = rq.voltage_V;
  s.tolerance_deg = rq.tolerance_deg;
  s.wait_ms = rq.wait_ms;
  s.timeout_ms = rq.timeout_ms;
  s.parameter_set = set;
  return s;
}

struct Stats {
  double peak = 0, sq = 0;
  std::size_t n = 0;
  double rms() const { return n ? std::sqrt(sq / static_cast<double>(n)) : 0.0; }
};

Stats torque_stats(const std::vector<TraceRow>& rows, std::size_t from, std::size_t to) {
  Stats s;
  for (std::size_t r = from; r < to && r < rows.size(); ++r) {
    s.peak = std::max(s.peak, std::abs(rows[r].torque_Nm));
    s.sq += rows[r].torque_Nm * rows[r].torque_Nm;
    ++s.n;
  }
  return s;
}

} // namespace

CycleEvaluation evaluate_cycle(const CycleRequest& rq, const CyclePlan& plan, const std::vector<MotionSetting>& settings,
                               bool keep_trace) {
  const TwinConfig cfg = sizing_twin_config(rq);
  const std::unique_ptr<Twin> owner = make_twin(cfg);
  Twin& twin = *owner;
  const MotorModel& motor = rq.module.drive.motor;
  const Thermal thermal(cfg.thermal, rq.module.thermal);
  const double cycle_s = cfg.cycle_s;

  CycleEvaluation ev;
  ev.torque_capability_Nm = motor.peak_torque_Nm();
  std::vector<MotionLimits> limits;
  for (std::size_t k = 0; k < plan.sets.size(); ++k) {
    ev.sets.push_back(make_parameter_set(set_request(rq, plan.sets[k].set), settings[k], plan.sets[k].load_gcm2));
    const MotionSetting& s = ev.sets.back().setting;
    limits.push_back(limits_from_parameter_set(s.speed_dps, s.accel_pct, s.jerk_pct, ev.sets.back().load_gcm2));
    write_all(twin, ev.sets.back().writes);
  }
  ev.tracking_limit_deg = read_display(twin, param::kTrackingErrorMax);
  ev.supply.bus_max_V = read_display(twin, param::kMotorVoltageMax);
  ev.handshake_s = rq.handshake_cycles * cycle_s; // A-SIZE-16

  Reasons reasons;
  ProcessDataOut pd;
  pd.motor_on = true;
  twin.set_pd_out(pd);
  if (!run_until(twin, [&] { return twin.pd_in().ready || twin.pd_in().error; }, kSwitchOnCycles) ||
      !twin.pd_in().ready) {
    reasons.add("switch_on", "motor did not switch on: " + error_text(twin.pd_in().error_code));
  }

  ev.segments.resize(rq.segments.size());
  const std::size_t first_move_row = twin.trace().size();
  int64_t last_target = 0;            // wire counts: the device's last target (relative moves start there)
  bool load_is_initial = true;
  int moves_total = 0, moves_done = 0;
  // Unsimulated dwell time of the last repetition (A-SIZE-9): s and mean torque^2 / loss of its hold.
  struct Extra { double s, sq, loss; };
  std::vector<Extra> extras;
  auto mean_of = [&](std::size_t from, std::size_t to) {
    double sq = 0, loss = 0;
    std::size_t n = 0;
    for (std::size_t r = from; r < to; ++r) {
      const TraceRow& row = twin.trace()[r];
      sq += row.torque_Nm * row.torque_Nm;
      loss += motor.copper_loss_W(row.torque_Nm) + thermal.speed_loss_W(deg_to_rad(row.velocity_dps));
      ++n;
    }
    return std::pair{n ? sq / static_cast<double>(n) : 0.0, n ? loss / static_cast<double>(n) : 0.0};
  };

  for (int rep = 0; rep < rq.cycles && reasons.list.empty(); ++rep) {
    const bool last = rep == rq.cycles - 1;
    if (last) ev.last_repetition_row = twin.trace().size();
    for (std::size_t i = 0; i < rq.segments.size(); ++i) { // a segment not reached stays empty (not completed)
      ev.segments[i] = SegmentResult{};
      ev.segments[i].kind = std::holds_alternative<CycleMove>(rq.segments[i].what)    ? "move"
                            : std::holds_alternative<CycleDwell>(rq.segments[i].what) ? "dwell"
                                                                                      : "load";
    }
    if (!load_is_initial) { // A-SIZE-19: every repetition starts with the file's load
      twin.set_load(rq.load);
      load_is_initial = true;
    }
    for (std::size_t i = 0; i < rq.segments.size() && reasons.list.empty(); ++i) {
      SegmentResult& sr = ev.segments[i];
      const std::size_t row_from = twin.trace().size();
      if (const auto* m = std::get_if<CycleMove>(&rq.segments[i].what)) {
        const std::size_t k = static_cast<std::size_t>(plan.move_set[i]);
        const ParameterSetValues& set = ev.sets[k];
        const int64_t wire = deg_to_wire_counts(m->target_deg);
        const int64_t end = m->relative ? last_target + wire : wire;
        sr = SegmentResult{};
        sr.kind = "move";
        sr.parameter_set = set.set;
        sr.start_deg = wire_counts_to_deg(last_target);
        sr.target_deg = wire_counts_to_deg(end);
        sr.load_gcm2 = std::max(0.0, twin.load_inertia_gcm2()); // what the flange carries now (MuJoCo)
        sr.process_torque_Nm = m->process_torque_Nm.value_or(rq.process_torque_Nm);
        const int64_t distance = end - last_target;
        sr.travel_s = distance == 0 ? 0.0
                                    : Profile::rest_to_rest(internal_counts_to_rad(distance * kInternalPerWireCount),
                                                            limits[k]).duration_s();
        // Process torque opposes the motion (A-SIZE-21), from the Move
        // command until the next segment sets its own.
        twin.set_external_torque(distance > 0 ? -sr.process_torque_Nm : distance < 0 ? sr.process_torque_Nm : 0.0);
        pd.target_position = static_cast<int32_t>(m->relative ? wire : end);
        pd.relative = m->relative;
        pd.parameter_set = static_cast<uint8_t>(set.set);
        pd.move = true;
        const std::size_t records_before = twin.moves().size();
        twin.set_pd_out(pd);
        ++moves_total;
        const int max_cycles = cycles_for(sr.travel_s + set.timeout_ms * 1e-3 + kMoveSlack_s, cycle_s);
        const bool ended = run_until(twin, [&] { const auto in = twin.pd_in(); return in.done || in.error; }, max_cycles);
        const ProcessDataIn in = twin.pd_in();
        const std::size_t row_done = twin.trace().size();
        last_target = end;
        if (twin.moves().size() > records_before) {
          const MoveRecord& rec = twin.moves().back();
          sr.max_tracking_error_deg = rec.max_tracking_error_deg;
          sr.completed = rec.completed() && in.done && !in.error;
          if (sr.completed && rec.settling_s) {
            sr.settling_s = *rec.settling_s; // A-SIZE-7
            sr.positioning_s = sr.travel_s + *rec.settling_s;
          }
        }
        const Stats st = torque_stats(twin.trace(), row_from, row_done);
        sr.peak_torque_Nm = st.peak;
        sr.rms_torque_Nm = st.rms();
        sr.duration_s = sr.positioning_s >= 0 ? sr.positioning_s + ev.handshake_s : 0.0;
        if (in.error) {
          reasons.add(category_of_error(in.error_code), fmt::format("segment {} (line {}), move to {} deg failed: {}", i + 1,
                                                                    rq.segments[i].line, sr.target_deg,
                                                                    error_text(in.error_code)));
          break;
        }
        if (!ended || !sr.completed) {
          reasons.add("settling", fmt::format("segment {} (line {}), move to {} deg did not complete within {:.3f} s",
                                              i + 1, rq.segments[i].line, sr.target_deg, max_cycles * cycle_s));
          break;
        }
        ++moves_done;
        pd.move = false; // T7: Move low for at least one cycle before the next command
        twin.set_pd_out(pd);
        twin.run_cycle();
      } else if (const auto* d = std::get_if<CycleDwell>(&rq.segments[i].what)) {
        sr = SegmentResult{};
        sr.kind = "dwell";
        sr.duration_s = d->dwell_s;
        sr.process_torque_Nm = d->process_torque_Nm;
        const double simulated_s = std::min(d->dwell_s, kMaxSimulatedDwell_s);
        twin.set_external_torque(d->process_torque_Nm);
        run_until(twin, [&] { return twin.pd_in().error; }, cycles_for(simulated_s, cycle_s));
        const auto [sq, loss] = mean_of(row_from, twin.trace().size());
        sr.hold_rms_torque_Nm = std::sqrt(sq);
        if (last && d->dwell_s > simulated_s) extras.push_back({d->dwell_s - simulated_s, sq, loss});
      } else {
        sr = SegmentResult{};
        sr.kind = "load";
        twin.set_load(std::get<CycleLoadChange>(rq.segments[i].what).load);
        load_is_initial = false;
      }
      if (twin.pd_in().error && reasons.list.empty()) {
        reasons.add(category_of_error(twin.pd_in().error_code),
                    fmt::format("segment {} (line {}): {}", i + 1, rq.segments[i].line, error_text(twin.pd_in().error_code)));
      }
      sr.row_from = row_from;
      sr.row_to = twin.trace().size();
    }
  }
  ev.sim_time_s = twin.time_s();
  ev.completed = reasons.list.empty() && moves_done == moves_total;

  // Over all moves of all repetitions: peak torque, headroom, warnings (A-SIZE-8).
  const std::vector<TraceRow>& rows = twin.trace();
  const TorqueScan scan = scan_torque(rows, first_move_row, ev);
  for (const SegmentResult& s : ev.segments) {
    ev.max_tracking_error_deg = std::max(ev.max_tracking_error_deg, s.max_tracking_error_deg);
    ev.cycle_s += s.duration_s;
  }
  ev.cycles_per_min = ev.completed && ev.cycle_s > 0 ? 60.0 / ev.cycle_s : 0.0;
  if (ev.completed) { // RMS torque and mean loss of the last repetition, long dwells included (A-SIZE-9)
    const auto [sq, loss] = mean_of(ev.last_repetition_row, rows.size());
    const double sim_s = static_cast<double>(rows.size() - ev.last_repetition_row) * cycle_s;
    double sq_s = sq * sim_s, loss_s = loss * sim_s, total_s = sim_s;
    for (const Extra& e : extras) {
      sq_s += e.sq * e.s;
      loss_s += e.loss * e.s;
      total_s += e.s;
    }
    if (total_s > 0) {
      ev.rms_torque_Nm = std::sqrt(sq_s / total_s);
      ev.mean_loss_W = loss_s / total_s;
    }
  }
  derive_figures(rq.module, rows, first_move_row, ev.last_repetition_row, cycle_s, rq.ambient_C, rq.thermal_margin_K, ev);
  // The same checks and margins as a single move (A-SIZE-5).
  judge_into(limit_figures(ev, scan, rq.voltage_V, rq.ambient_C, rq.thermal_margin_K), std::move(reasons), ev);
  if (keep_trace) ev.trace = rows;
  return ev;
}

} // namespace sreh::sizing
