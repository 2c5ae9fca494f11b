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
#include "sizing/plc_handshake.hpp"
#include "sizing/run_parts.hpp"
#include "sizing/thermal_estimate.hpp"
#include "sizing/twin_factory.hpp"
#include "twin/thermal.hpp"

namespace sreh::sizing {
namespace {

// A SizingRequest carrying the cycle's set-wide values, for make_parameter_set.
SizingRequest set_request(const CycleRequest& rq, int set) {
  SizingRequest s;
  s.world = rq.world; // the supply decides the index 85 writes
  s.settling = rq.settling;
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

// Unsimulated dwell time of the last repetition (A-SIZE-9): s and mean torque^2 / loss of its hold.
struct Extra {
  double s, sq, loss;
};

// The segments in order, `cycles` times (A-SIZE-17), on one twin; what the
// figures afterwards need (extras, counts) is collected on the way.
struct CycleRun {
  CycleRun(const CycleRequest& request, const CyclePlan& cycle_plan, const std::vector<MotionLimits>& set_limits,
           Twin& run_twin, const Thermal& run_thermal, CycleEvaluation& evaluation, Reasons& run_reasons,
           double master_cycle_s)
      : rq(request), plan(cycle_plan), limits(set_limits), twin(run_twin), thermal(run_thermal), ev(evaluation),
        reasons(run_reasons), cycle_s(master_cycle_s) {}

  const CycleRequest& rq;
  const CyclePlan& plan;
  const std::vector<MotionLimits>& limits; // per set of the plan
  Twin& twin;
  const Thermal& thermal;
  CycleEvaluation& ev;
  Reasons& reasons;
  double cycle_s; // the master cycle
  PlcHandshake plc{twin};
  int64_t last_target = 0; // wire counts: the device's last target (relative moves start there)
  bool load_is_initial = true;
  int moves_total = 0, moves_done = 0;
  std::vector<Extra> extras;

  // Mean torque^2 and loss over trace rows [from, to).
  std::pair<double, double> mean_of(std::size_t from, std::size_t to) const {
    const MotorModel& motor = rq.world.module.drive.motor;
    double sq = 0, loss = 0;
    std::size_t n = 0;
    for (std::size_t r = from; r < to; ++r) {
      const TraceRow& row = twin.trace()[r];
      sq += row.torque_Nm * row.torque_Nm;
      loss += motor.copper_loss_W(row.torque_Nm) + thermal.speed_loss_W(deg_to_rad(row.velocity_dps));
      ++n;
    }
    return std::pair{n ? sq / static_cast<double>(n) : 0.0, n ? loss / static_cast<double>(n) : 0.0};
  }

  // A move segment; false when it failed (the reason added).
  bool move(std::size_t i, const CycleMove& m, SegmentResult& sr, std::size_t row_from) {
    const std::size_t k = static_cast<std::size_t>(plan.move_set[i]);
    const ParameterSetValues& set = ev.sets[k];
    const int64_t wire = deg_to_wire_counts(m.target_deg);
    const int64_t end = m.relative ? last_target + wire : wire;
    sr = SegmentResult{};
    sr.kind = "move";
    sr.parameter_set = set.set;
    sr.start_deg = wire_counts_to_deg(last_target);
    sr.target_deg = wire_counts_to_deg(end);
    sr.load_gcm2 = std::max(0.0, twin.load_inertia_gcm2()); // what the flange carries now (MuJoCo)
    sr.process_torque_Nm = m.process_torque_Nm.value_or(rq.process_torque_Nm);
    const int64_t distance = end - last_target;
    sr.travel_s = distance == 0 ? 0.0
                                : Profile::rest_to_rest(internal_counts_to_rad(distance * kInternalPerWireCount),
                                                        limits[k]).duration_s();
    // Process torque opposes the motion (A-SIZE-21), from the Move command
    // until the next segment sets its own.
    twin.set_external_torque(distance > 0 ? -sr.process_torque_Nm : distance < 0 ? sr.process_torque_Nm : 0.0);
    ++moves_total;
    const int max_cycles = cycles_for(sr.travel_s + set.timeout_ms * 1e-3 + kMoveSlack_s, cycle_s);
    const PlcHandshake::MoveEnd done = plc.move(static_cast<int32_t>(m.relative ? wire : end), m.relative,
                                                static_cast<uint8_t>(set.set), max_cycles);
    last_target = end;
    if (done.record) {
      sr.max_tracking_error_deg = done.record->max_tracking_error_deg;
      sr.completed = done.record->completed() && done.in.done && !done.in.error;
      if (sr.completed && done.record->settling_s) {
        sr.settling_s = *done.record->settling_s; // A-SIZE-7
        sr.positioning_s = sr.travel_s + *done.record->settling_s;
      }
    }
    const Stats st = torque_stats(twin.trace(), row_from, done.row_done);
    sr.peak_torque_Nm = st.peak;
    sr.rms_torque_Nm = st.rms();
    sr.duration_s = sr.positioning_s >= 0 ? sr.positioning_s + ev.handshake_s : 0.0;
    const std::string where = fmt::format("segment {} (line {}), move to {} deg", i + 1, rq.segments[i].line, sr.target_deg);
    if (done.in.error) {
      reasons.add(category_of_error(done.in.error_code), fmt::format("{} failed: {}", where, error_text(done.in.error_code)));
      return false;
    }
    if (!done.ended || !sr.completed) {
      reasons.add("settling", fmt::format("{} did not complete within {:.3f} s", where, max_cycles * cycle_s));
      return false;
    }
    ++moves_done;
    plc.drop_move(); // T7: Move low for at least one cycle before the next command
    twin.run_cycle();
    return true;
  }

  void dwell(const CycleDwell& d, SegmentResult& sr, std::size_t row_from, bool last) {
    sr = SegmentResult{};
    sr.kind = "dwell";
    sr.duration_s = d.dwell_s;
    sr.process_torque_Nm = d.process_torque_Nm;
    const double simulated_s = std::min(d.dwell_s, kMaxSimulatedDwell_s);
    twin.set_external_torque(d.process_torque_Nm);
    run_until(twin, [&] { return twin.pd_in().error; }, cycles_for(simulated_s, cycle_s));
    const auto [sq, loss] = mean_of(row_from, twin.trace().size());
    sr.hold_rms_torque_Nm = std::sqrt(sq);
    if (last && d.dwell_s > simulated_s) extras.push_back({d.dwell_s - simulated_s, sq, loss});
  }

  // One repetition of the segment list; a segment not reached stays empty (not completed).
  void repetition(bool last) {
    if (last) ev.last_repetition_row = twin.trace().size();
    for (std::size_t i = 0; i < rq.segments.size(); ++i) {
      ev.segments[i] = SegmentResult{};
      ev.segments[i].kind = std::holds_alternative<CycleMove>(rq.segments[i].what)    ? "move"
                            : std::holds_alternative<CycleDwell>(rq.segments[i].what) ? "dwell"
                                                                                      : "load";
    }
    if (!load_is_initial) { // A-SIZE-19: every repetition starts with the file's load
      twin.set_load(rq.world.load);
      load_is_initial = true;
    }
    for (std::size_t i = 0; i < rq.segments.size() && reasons.list.empty(); ++i) {
      SegmentResult& sr = ev.segments[i];
      const std::size_t row_from = twin.trace().size();
      if (const auto* m = std::get_if<CycleMove>(&rq.segments[i].what)) {
        if (!move(i, *m, sr, row_from)) break;
      } else if (const auto* d = std::get_if<CycleDwell>(&rq.segments[i].what)) {
        dwell(*d, sr, row_from, last);
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
};

// RMS torque and mean loss of the last repetition, long dwells included (A-SIZE-9).
void repetition_means(const CycleRun& run, double cycle_s, CycleEvaluation& ev) {
  const std::size_t rows = run.twin.trace().size();
  const auto [sq, loss] = run.mean_of(ev.last_repetition_row, rows);
  const double sim_s = static_cast<double>(rows - ev.last_repetition_row) * cycle_s;
  double sq_s = sq * sim_s, loss_s = loss * sim_s, total_s = sim_s;
  for (const Extra& e : run.extras) {
    sq_s += e.sq * e.s;
    loss_s += e.loss * e.s;
    total_s += e.s;
  }
  if (total_s > 0) {
    ev.rms_torque_Nm = std::sqrt(sq_s / total_s);
    ev.mean_loss_W = loss_s / total_s;
  }
}

} // namespace

CycleEvaluation evaluate_cycle(const CycleRequest& rq, const CyclePlan& plan, const std::vector<MotionSetting>& settings,
                               bool keep_trace) {
  if (rq.on_simulation) rq.on_simulation();
  const TwinConfig cfg = sizing_twin_config(rq.world);
  const PooledTwin lent = fresh_twin(cfg); // as make_twin(cfg) builds it (issue 31)
  Twin& twin = *lent;
  const Thermal thermal(cfg.thermal, rq.world.module.thermal);
  const double cycle_s = cfg.cycle_s;

  CycleEvaluation ev;
  ev.torque_capability_Nm = rq.world.module.drive.motor.peak_torque_Nm();
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
  CycleRun run(rq, plan, limits, twin, thermal, ev, reasons, cycle_s);
  if (auto failed = run.plc.switch_on(0)) reasons.add("switch_on", std::move(*failed));
  ev.segments.resize(rq.segments.size());
  const std::size_t first_move_row = twin.trace().size();
  for (int rep = 0; rep < rq.cycles && reasons.list.empty(); ++rep) run.repetition(rep == rq.cycles - 1);
  ev.sim_time_s = twin.time_s();
  ev.completed = reasons.list.empty() && run.moves_done == run.moves_total;

  // Over all moves of all repetitions: peak torque, headroom, warnings (A-SIZE-8).
  const std::vector<TraceRow>& rows = twin.trace();
  const TorqueScan scan = scan_torque(rows, first_move_row, ev);
  for (const SegmentResult& s : ev.segments) {
    ev.max_tracking_error_deg = std::max(ev.max_tracking_error_deg, s.max_tracking_error_deg);
    ev.cycle_s += s.duration_s;
  }
  ev.cycles_per_min = ev.completed && ev.cycle_s > 0 ? 60.0 / ev.cycle_s : 0.0;
  if (ev.completed) repetition_means(run, cycle_s, ev);
  derive_figures(rq.world.module, rows, first_move_row, ev.last_repetition_row, cycle_s, rq.world.thermal.ambient_C, rq.thermal_margin_K, ev);
  // The same checks and margins as a single move (A-SIZE-5).
  judge_into(limit_figures(ev, scan, rq.world.supply.voltage_V, rq.world.thermal.ambient_C, rq.thermal_margin_K), std::move(reasons), ev);
  if (keep_trace) ev.trace = rows;
  return ev;
}

} // namespace sreh::sizing
