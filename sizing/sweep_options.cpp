#include "sizing/sweep_options.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <tuple>
#include <vector>

#include <fmt/format.h>

#include "device_logic/parameter_ids.hpp"
#include "io/atomic_file.hpp"
#include "io/cpus.hpp"
#include "io/figures.hpp"
#include "io/output_path.hpp"
#include "io/shard.hpp"
#include "twin/load_builder.hpp"
#include "sizing/report.hpp"
#include "sizing/report_provenance.hpp"
#include "sizing/sizing.hpp"

namespace sreh::sizing {
namespace {

// The ranges in the help are the parameter table's rows (manual 6.2), never retyped.
std::string sweep_row_range(ParamId row) { return fmt::format("{} .. {}", display_min(row), display_max(row)); }
const param::MotionSet kSweepSet(0);
const std::string kLoadsHelp = fmt::format("Load inertias, comma separated, 0 .. {} g cm^2", max_load_gcm2());
const std::string kVoltagesHelp = fmt::format("Supply voltages {} .. {} V, comma separated", min_voltage_V(), max_voltage_V());
const std::string kSweepAccelHelp = fmt::format("Acceleration with --speeds-dps, {} %", sweep_row_range(kSweepSet.acceleration));
const std::string kSweepJerkHelp = fmt::format("Jerk with --speeds-dps, {} %", sweep_row_range(kSweepSet.jerk));

using W = SweepOptions;
const OptionSpec<W> kSweepOptions[] = {
    {"loads-gcm2", kLoadsHelp, &W::loads_gcm2, true},
    {"angles-deg", "Move angles in deg, comma separated", &W::angles_deg, true},
    {"voltages-V", kVoltagesHelp, &W::voltages_V, false, true},
    {"speeds-dps", "Evaluate these speeds in deg/s (comma separated) instead of recommending [default: recommend]", &W::speeds_dps},
    {"accel-pct", kSweepAccelHelp, &W::accel_pct, false, true},
    {"jerk-pct", kSweepJerkHelp, &W::jerk_pct, false, true},
    {"dwell-s", "Pause after each move, s", &W::dwell_s, false, true},
    {"tolerance-deg", "Position tolerance in deg (index 64+n.5)", &W::tolerance_deg, false, true},
    {"wait-ms", "Waiting time in ms (index 64+n.6)", &W::wait_ms, false, true},
    {"timeout-ms", "Settling timeout in ms (index 64+n.7) [default: wait + 75 ms, >= 100 ms]", &W::timeout_ms},
    {"ambient-C", "Ambient temperature, degC", &W::ambient_C, false, true},
    {"cycles", "Back-and-forth cycles simulated per evaluation", &W::cycles, false, true},
    {"threads", "Worker threads 1 .. 64 [default: the CPUs this process may use, fewer if SLURM_CPUS_PER_TASK says so]", &W::threads},
    {"csv", "Write the results to this CSV file (one row per grid point)", &W::csv},
    {"report", "Write an HTML report with plots into this folder", &W::report},
    {"model", "Model card overrides (YAML as `sreh-twin model show` prints): the module's physical constants", &W::model},
    {"shard", "Run only shard i of N and start the CSV with a shard line for `sweep merge`: i/N (rerun of one task of a Slurm array 1-N: $SLURM_ARRAY_TASK_ID/N), auto (Slurm array, FIRST-LAST[:STEP]), auto/N (Kubernetes indexed Job)", &W::shard},
    {"targets-s", "Target positioning times in s for the heaviest-load plot, comma separated [default: 8 spanning the feasible times]", &W::targets_s},
    {"uncertainty", "Also evaluate each point on models sampled over the model card's ranges: _lo / _hi columns", &W::uncertainty},
    {"samples", "With --uncertainty: models sampled per point, 2 .. 1000 (Latin hypercube)", &W::samples, false, true},
    {"seed", "With --uncertainty: seed of the sampling", &W::seed, false, true},
};

constexpr SweepColumnSpec kColumns[] = {
    {"load_gcm2", SweepColumnKind::Number},       {"angle_deg", SweepColumnKind::Number},
    {"voltage_V", SweepColumnKind::Number},       {"mode", SweepColumnKind::Word},
    {"speed_dps", SweepColumnKind::Number},       {"accel_pct", SweepColumnKind::Number},
    {"jerk_pct", SweepColumnKind::Number},        {"travel_s", SweepColumnKind::Number},
    {"settling_s", SweepColumnKind::Number},      {"positioning_s", SweepColumnKind::Number},
    {"cycle_s", SweepColumnKind::Number},         {"cycles_per_min", SweepColumnKind::Number},
    {"peak_torque_Nm", SweepColumnKind::Number},  {"rms_torque_Nm", SweepColumnKind::Number},
    {"max_tracking_error_deg", SweepColumnKind::Number}, {"steady_temperature_C", SweepColumnKind::Number},
    {"time_to_warning_s", SweepColumnKind::Number}, {"feasible", SweepColumnKind::Flag},
    {"simulations", SweepColumnKind::Count},      {"reason", SweepColumnKind::Text},
};
constexpr std::size_t kBaseColumns = std::size(kColumns);
// Added after those by `--uncertainty` (issue 26).
constexpr SweepColumnSpec kBandColumns[] = {
    {"positioning_s_lo", SweepColumnKind::Number}, {"positioning_s_hi", SweepColumnKind::Number},
    {"settling_s_lo", SweepColumnKind::Number},   {"settling_s_hi", SweepColumnKind::Number},
    {"peak_torque_Nm_lo", SweepColumnKind::Number}, {"peak_torque_Nm_hi", SweepColumnKind::Number},
    {"steady_temperature_C_lo", SweepColumnKind::Number}, {"steady_temperature_C_hi", SweepColumnKind::Number},
    {"feasible_worst_case", SweepColumnKind::Flag},
};

// Times of an evaluation whose moves did not all complete mean nothing: missing.
SweepCell time_if(bool completed, double v) { return completed ? SweepCell(v) : SweepCell(); }

} // namespace

std::span<const OptionSpec<SweepOptions>> sweep_option_table() { return kSweepOptions; }

SweepRequest make_sweep_request(const SweepOptions& a) {
  if (a.threads < 0 || a.threads > 64) throw SizingInputError(fmt::format("--threads {}: expected 1 .. 64", a.threads));
  for (double t : a.targets_s) {
    if (!(t > 0)) throw SizingInputError(fmt::format("--targets-s {}: target times must be positive", t));
  }
  SweepRequest rq;
  rq.loads_gcm2 = a.loads_gcm2;
  rq.angles_deg = a.angles_deg;
  rq.voltages_V = a.voltages_V;
  rq.speeds_dps = a.speeds_dps;
  rq.accel_pct = a.accel_pct;
  rq.jerk_pct = a.jerk_pct;
  rq.base.dwell_s = a.dwell_s;
  rq.base.settling.tolerance_deg = a.tolerance_deg;
  rq.base.settling.wait_ms = a.wait_ms;
  rq.base.settling.timeout_ms = a.timeout_ms;
  rq.base.world.thermal.ambient_C = a.ambient_C;
  rq.base.cycles = a.cycles;
  rq.base.world.module = module_from_option(a.model);
  if (a.uncertainty) {
    if (a.samples < 2 || a.samples > 1000) throw SizingInputError(fmt::format("--samples {}: expected 2 .. 1000", a.samples));
    rq.uncertainty = true;
    rq.samples = a.samples;
    rq.seed = static_cast<uint64_t>(a.seed);
    rq.card = a.model.empty() ? default_model_card() : apply_model_file(default_model_card(), a.model);
  }
  if (!a.shard.empty()) {
    if (!a.report.empty()) throw SizingInputError("--shard with --report: merge the parts, then report the whole sweep");
    try {
      std::tie(rq.shard, rq.shards) = io::parse_shard(a.shard, [](const char* name) -> const char* { return std::getenv(name); });
    } catch (const std::invalid_argument& e) {
      throw SizingInputError(e.what());
    }
  }
  try { // not hardware_concurrency(): a Slurm task or a cpuset may use fewer CPUs than the node has (issue 31)
    rq.threads = a.threads > 0 ? a.threads
                               : io::default_threads([](const char* n) -> const char* { return std::getenv(n); }, 64);
  } catch (const std::invalid_argument& e) {
    throw SizingInputError(e.what());
  }
  return rq;
}

SweepResult run_sweep_command(const SweepOptions& a, const SweepRequest& rq) {
  if (!a.report.empty() && !reports_available()) throw SizingInputError("--report: this build has no renders");
  try { // the one output rule, before any work (issue 12)
    io::check_outputs({{"--csv", a.csv, io::OutputKind::File}, {"--report", a.report, io::OutputKind::Folder}}, {});
  } catch (const io::PathError& e) {
    throw SizingInputError(e.what());
  }
  SweepResult result = run_sweep(rq);
  try {
    if (!a.csv.empty()) {
      io::write_file_atomic(a.csv, [&](std::ostream& out) {
        if (!a.shard.empty()) out << shard_marker(result); // for `sweep merge`, 1/1 too (issue 31)
        write_sweep_csv(out, result);
      });
    }
    if (!a.report.empty() && rq.shards == 1) {
      const std::vector<double> targets = a.targets_s.empty() ? default_targets_s(result) : a.targets_s;
      write_report_page(a.report, sweep_report_html(rq, result, targets), sweep_provenance(rq));
    }
  } catch (const std::runtime_error& e) {
    throw SizingInputError(e.what());
  }
  return result;
}

std::span<const SweepColumnSpec> sweep_columns(bool uncertainty) {
  static const std::vector<SweepColumnSpec> with_bands = [] {
    std::vector<SweepColumnSpec> v(std::begin(kColumns), std::end(kColumns));
    v.insert(v.end(), std::begin(kBandColumns), std::end(kBandColumns));
    return v;
  }();
  if (uncertainty) return with_bands;
  return kColumns;
}

namespace {

SweepCell exact_cell(const SweepPoint& p, std::size_t column) {
  const Evaluation& e = p.result.evaluation;
  switch (column) {
    case 0: return p.load_gcm2;
    case 1: return p.angle_deg;
    case 2: return p.voltage_V;
    case 3: return std::string(p.result.recommended ? "recommend" : "evaluate");
    case 4: return e.set.tidy.speed_dps;
    case 5: return e.set.tidy.accel_pct;
    case 6: return e.set.tidy.jerk_pct;
    case 7: return e.travel_s;
    case 8: return time_if(e.completed, e.settling_s);
    case 9: return time_if(e.completed, e.positioning_s);
    case 10: return time_if(e.completed, e.cycle_s);
    case 11: return time_if(e.completed, e.cycles_per_min);
    case 12: return e.peak_torque_Nm;
    case 13: return e.rms_torque_Nm;
    case 14: return e.max_tracking_error_deg;
    case 15: return e.steady_temperature_C;
    case 16: return e.time_to_warning_s ? SweepCell(*e.time_to_warning_s) : SweepCell();
    case 17: return e.feasible;
    case 18: return static_cast<int64_t>(p.result.simulations);
    case 19: return e.reason;
    default: break;
  }
  if (!p.uncertainty || column < kBaseColumns || (p.uncertainty->banded == 0 && column - kBaseColumns < 8)) return {};
  const UncertaintyResult& u = *p.uncertainty;
  switch (column - kBaseColumns) {
    case 0: return u.positioning_s.lo;
    case 1: return u.positioning_s.hi;
    case 2: return u.settling_s.lo;
    case 3: return u.settling_s.hi;
    case 4: return u.peak_torque_Nm.lo;
    case 5: return u.peak_torque_Nm.hi;
    case 6: return u.max_temperature_C.lo;
    case 7: return u.max_temperature_C.hi;
    case 8: return u.feasible_worst_case;
    default: return {};
  }
}

} // namespace

// At the column's resolution (issue 29): the CSV and Python's columns agree.
SweepCell sweep_cell(const SweepPoint& p, std::size_t column) {
  SweepCell cell = exact_cell(p, column);
  if (auto* v = std::get_if<double>(&cell)) *v = io::round_figure(sweep_columns(true)[column].name, *v);
  return cell;
}

} // namespace sreh::sizing
