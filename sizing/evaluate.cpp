// One parameter set in the twin, as a PLC would run it (interfaces.md: the
// device only sees process data and ISDU): the set written to 64+n over
// ISDU, Motor On, then 0 -> A -> 0 moves with the dwell after each Done.
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "device_logic/fault_names.hpp"
#include "device_logic/faults.hpp"
#include "device_logic/motor_model.hpp"
#include "device_logic/parameter_ids.hpp"
#include "device_logic/parameter_table.hpp"
#include "device_logic/planner.hpp"
#include "device_logic/units.hpp"
#include "sizing/plc_handshake.hpp"
#include "sizing/run_parts.hpp"
#include "sizing/sizing.hpp"
#include "sizing/thermal_estimate.hpp"
#include "sizing/twin_factory.hpp"
#include "twin/thermal.hpp"

namespace sreh::sizing {

namespace {
// "error 0x08: position tracking error (114.5)": the one table of names (issue 39).
std::string code_text(EventType type, uint8_t code) {
  std::string s;
  for (uint8_t bit = 0; bit < 8; ++bit) {
    if (!(code & (1u << bit))) continue;
    s += (s.empty() ? "" : ", ") + fmt::format("{} ({})", mid_sentence(bit_name(type, bit)),
                                               cause_index(type, cause_subindex(type, bit)));
  }
  return fmt::format("{} 0x{:02X}: {}", type == EventType::Error ? "error" : "warning", code, s);
}
} // namespace

// Shared with the cycle evaluation (run_parts.hpp).
std::string error_text(uint8_t code) { return code_text(EventType::Error, code); }
std::string warning_text(uint8_t code) { return code_text(EventType::Warning, code); }

void write_all(Twin& twin, const std::vector<IsduWrite>& writes) {
  for (const IsduWrite& w : writes) {
    const ParameterEntry* row = find_parameter(w.index, w.subindex);
    if (row == nullptr) throw std::logic_error(fmt::format("sizing: no parameter {}.{}", w.index, w.subindex));
    const IsduResult r = twin.isdu_write(w.index, w.subindex, encode_number(row->type, w.value));
    if (!r.ok()) {
      throw std::logic_error(fmt::format("sizing: the device refused {}.{} = {} (0x{:04X})", w.index, w.subindex,
                                         w.value, r.error));
    }
  }
}

double read_display(Twin& twin, ParamId id) {
  const IsduResult r = twin.isdu_read(id.index, id.subindex);
  if (!r.ok() || r.data.size() != wire_size(parameter_row(id).type)) return 0;
  return raw_to_display(id, decode_number(parameter_row(id).type, r.data));
}

// The limit an error code points at (manual 7.2).
std::string category_of_error(uint8_t code) {
  if (code & (1u << static_cast<int>(ErrorBit::TrackingError))) return "tracking";
  if (code & (1u << static_cast<int>(ErrorBit::Positioning))) return "settling";
  if (code & (1u << static_cast<int>(ErrorBit::Temperature))) return "temperature";
  if (code & (1u << static_cast<int>(ErrorBit::MotorVoltage))) return "voltage";
  return "device_error";
}

int cycles_for(double seconds, double cycle_s) {
  return static_cast<int>(std::ceil(seconds / cycle_s - 1e-9));
}

namespace {

double read_tracking_limit_deg(Twin& twin) { return read_display(twin, param::kTrackingErrorMax); }

} // namespace

// A-SIZE-15: the bus power of one sample: mechanical power plus the
// winding's copper loss (the output stage taken as lossless).
double bus_power_W(const MotorModel& motor, const TraceRow& row) {
  return row.torque_Nm * deg_to_rad(row.velocity_dps) + motor.copper_loss_W(row.torque_Nm);
}

SupplyFigures supply_figures(const MotorModel& motor, const std::vector<TraceRow>& rows, std::size_t from,
                             std::size_t cycle_from, double dt_s, double bus_max_V) {
  SupplyFigures f;
  f.bus_max_V = bus_max_V;
  double regen = 0, sq = 0;
  std::size_t n = 0;
  for (std::size_t r = from; r < rows.size(); ++r) {
    const double u = std::max(rows[r].supply_V, 1.0);
    const double p = bus_power_W(motor, rows[r]);
    const double i = std::max(0.0, p) / u;
    f.peak_current_A = std::max(f.peak_current_A, i);
    f.peak_bus_V = std::max(f.peak_bus_V, rows[r].supply_V);
    if (p < 0) {
      regen += -p * dt_s;
      f.regen_energy_J = std::max(f.regen_energy_J, regen);
    } else {
      regen = 0;
    }
    if (r >= cycle_from) {
      sq += i * i;
      ++n;
    }
  }
  f.rms_current_A = n ? std::sqrt(sq / static_cast<double>(n)) : 0.0;
  // Manual 7.2, 114.4 cause 2 "motor voltage too high ... In case of
  // overvoltage: install more capacity on the motor supply or a chopper".
  f.overvoltage_advice = bus_max_V > 0 && f.peak_bus_V > bus_max_V;
  return f;
}

namespace {

// Trace rows where the figures start (A-SIZE-8, A-SIZE-9).
struct Rows {
  std::size_t first_move = 0; // the first Move
  std::size_t last_cycle = 0; // the last full back-and-forth cycle
  std::size_t last_dwell = 0; // the last dwell
};

MoveResult move_result(const PlcHandshake::MoveEnd& end, double target_deg, double travel_s) {
  MoveResult mr;
  mr.target_deg = target_deg;
  mr.travel_s = travel_s;
  if (const std::optional<MoveRecord>& rec = end.record) {
    mr.max_tracking_error_deg = rec->max_tracking_error_deg;
    mr.overshoot_deg = rec->overshoot_deg;
    mr.in_window_s = rec->in_window_s.value_or(-1);
    mr.simulated_travel_s = rec->travel_s;
    mr.completed = rec->completed() && end.in.done && !end.in.error;
    if (mr.completed && rec->settling_s) {
      // A-SIZE-7: settling as simulated, from the end of the trajectory (b)
      // to Done (f); positioning = planned travel + settling (>= travel).
      mr.settling_s = *rec->settling_s;
      mr.positioning_s = travel_s + *rec->settling_s;
    }
  }
  return mr;
}

// Motor On, then the moves 0 -> A -> 0 ... (A-SIZE-3) with the dwell after
// each Done, until every move ran or one failed (its reason in `reasons`).
Rows run_moves(Twin& twin, const SizingRequest& rq, const ParameterSetValues& set, double cycle_s, Evaluation& ev,
               Reasons& reasons) {
  PlcHandshake plc(twin);
  if (auto failed = plc.switch_on(static_cast<uint8_t>(set.set))) reasons.add("switch_on", std::move(*failed));
  const int32_t target_wire = static_cast<int32_t>(deg_to_wire_counts(rq.angle_deg));
  const int move_cycles = cycles_for(ev.travel_s + set.timeout_ms * 1e-3 + kMoveSlack_s, cycle_s);
  const double simulated_dwell_s = std::min(rq.dwell_s, kMaxSimulatedDwell_s);
  const int dwell_cycles = std::max(1, cycles_for(simulated_dwell_s, cycle_s)); // Move must fall for one cycle (T7)
  const int moves = 2 * std::max(1, rq.cycles);
  Rows rows;
  rows.first_move = twin.trace().size();
  for (int i = 0; i < moves && reasons.list.empty(); ++i) {
    if (i == moves - 2) rows.last_cycle = twin.trace().size();
    const bool out = (i % 2) == 0;
    const PlcHandshake::MoveEnd end = plc.move(out ? target_wire : 0, false, static_cast<uint8_t>(set.set), move_cycles);
    ev.moves.push_back(move_result(end, out ? wire_counts_to_deg(target_wire) : 0.0, ev.travel_s));
    const MoveResult& mr = ev.moves.back();
    if (end.in.error) {
      reasons.add(category_of_error(end.in.error_code),
                  fmt::format("move {} to {} deg failed: {}", i + 1, mr.target_deg, error_text(end.in.error_code)));
      break;
    }
    if (!end.ended || !mr.completed) {
      reasons.add("settling", fmt::format("move {} to {} deg did not complete within {:.3f} s", i + 1, mr.target_deg,
                                          move_cycles * cycle_s));
      break;
    }
    plc.drop_move();
    rows.last_dwell = twin.trace().size();
    if (run_until(twin, [&] { return twin.pd_in().error; }, dwell_cycles)) {
      reasons.add(category_of_error(twin.pd_in().error_code),
                  fmt::format("after move {}: {}", i + 1, error_text(twin.pd_in().error_code)));
    }
    // Overshoot and the window entered for good are watched until the next move.
    if (const std::optional<MoveRecord> rec = plc.last_record()) {
      ev.moves.back().overshoot_deg = rec->overshoot_deg;
      ev.moves.back().in_window_s = rec->in_window_s.value_or(-1);
    }
  }
  return rows;
}

// RMS torque and mean loss over the last cycle; the unsimulated part of the
// dwells (A-SIZE-9) counts with the mean of the last simulated dwell.
void cycle_means(const SizingRequest& rq, const Thermal& thermal, const std::vector<TraceRow>& rows, const Rows& at,
                 double cycle_s, Evaluation& ev) {
  const MotorModel& motor = rq.world.module.drive.motor;
  struct Sums { double torque_sq = 0, loss = 0; std::size_t n = 0; };
  auto sums = [&](std::size_t from) {
    Sums s;
    for (std::size_t r = from; r < rows.size(); ++r) {
      s.torque_sq += rows[r].torque_Nm * rows[r].torque_Nm;
      s.loss += motor.copper_loss_W(rows[r].torque_Nm) + thermal.speed_loss_W(deg_to_rad(rows[r].velocity_dps));
      ++s.n;
    }
    return s;
  };
  const Sums cycle = sums(at.last_cycle);
  const Sums hold = sums(at.last_dwell);
  const double extra_s = 2.0 * std::max(0.0, rq.dwell_s - std::min(rq.dwell_s, kMaxSimulatedDwell_s));
  const double hold_sq = hold.n ? hold.torque_sq / static_cast<double>(hold.n) : 0.0;
  const double hold_loss = hold.n ? hold.loss / static_cast<double>(hold.n) : 0.0;
  const double sim_s = static_cast<double>(cycle.n) * cycle_s;
  const double total_s = sim_s + extra_s;
  if (total_s > 0) {
    ev.rms_torque_Nm = std::sqrt((cycle.torque_sq * cycle_s + hold_sq * extra_s) / total_s);
    ev.mean_loss_W = (cycle.loss * cycle_s + hold_loss * extra_s) / total_s;
  }
}

} // namespace

Evaluation evaluate(const SizingRequest& rq, const ParameterSetValues& set, bool keep_trace) {
  if (rq.on_simulation) rq.on_simulation();
  const TwinConfig cfg = sizing_twin_config(rq.world);
  const PooledTwin lent = fresh_twin(cfg); // as make_twin(cfg) builds it (issue 31)
  Twin& twin = *lent;
  const MotorModel& motor = rq.world.module.drive.motor;
  const Thermal thermal(cfg.thermal, rq.world.module.thermal);

  Evaluation ev;
  ev.set = set;
  ev.load_gcm2 = std::max(0.0, twin.load_inertia_gcm2()); // no load reads -1e-12
  ev.torque_capability_Nm = motor.peak_torque_Nm();
  write_all(twin, set.writes);
  ev.tracking_limit_deg = read_tracking_limit_deg(twin);
  ev.supply.bus_max_V = read_display(twin, param::kMotorVoltageMax);

  // Travel time (manual 3.5.2 (1)): the device's own plan for that distance
  // and those limits, i.e. the time-optimal S-curve (device.cpp, T3).
  const int32_t target_wire = static_cast<int32_t>(deg_to_wire_counts(rq.angle_deg));
  const MotionLimits limits = limits_from_parameter_set(set.setting.speed_dps, set.setting.accel_pct,
                                                        set.setting.jerk_pct, set.load_gcm2);
  ev.travel_s = Profile::rest_to_rest(internal_counts_to_rad(int64_t{target_wire} * kInternalPerWireCount), limits)
                    .duration_s();

  Reasons reasons;
  const double cycle_s = cfg.cycle_s;
  const Rows at = run_moves(twin, rq, set, cycle_s, ev, reasons);
  ev.sim_time_s = twin.time_s();

  // Worst move (A-SIZE-7).
  for (const MoveResult& m : ev.moves) {
    ev.settling_s = std::max(ev.settling_s, m.settling_s);
    ev.positioning_s = std::max(ev.positioning_s, m.positioning_s);
    ev.max_tracking_error_deg = std::max(ev.max_tracking_error_deg, m.max_tracking_error_deg);
  }
  ev.handshake_s = rq.handshake_cycles * cfg.cycle_s; // A-SIZE-16
  ev.cycle_s = 2.0 * (ev.positioning_s + ev.handshake_s) + 2.0 * rq.dwell_s;
  ev.cycles_per_min = ev.cycle_s > 0 ? 60.0 / ev.cycle_s : 0.0;

  // Torque and losses from the trace (one sample per IO-Link cycle, A-SIZE-8).
  const std::vector<TraceRow>& rows = twin.trace();
  const TorqueScan scan = scan_torque(rows, at.first_move, ev);
  ev.completed = reasons.list.empty() && static_cast<int>(ev.moves.size()) == 2 * std::max(1, rq.cycles);
  if (ev.completed) cycle_means(rq, thermal, rows, at, cycle_s, ev);
  derive_figures(rq.world.module, rows, at.first_move, at.last_cycle, cycle_s, rq.world.thermal.ambient_C, rq.thermal_margin_K, ev);
  // Feasible with margin (A-SIZE-5); the same checks for a given set, for
  // every set the search tries and for cycles (judge(), limits.cpp).
  LimitFigures lf = limit_figures(ev, scan, rq.world.supply.voltage_V, rq.world.thermal.ambient_C, rq.thermal_margin_K);
  if (rq.max_positioning_ms) lf.positioning_target = std::pair{ev.positioning_s, *rq.max_positioning_ms * 1e-3};
  if (rq.max_cycle_ms) lf.cycle_target = std::pair{ev.cycle_s, *rq.max_cycle_ms * 1e-3};
  judge_into(lf, std::move(reasons), ev);
  if (keep_trace) ev.trace = rows;
  return ev;
}

} // namespace sreh::sizing
