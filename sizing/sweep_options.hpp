// `sreh-twin sweep` and `sreh_twin.sweep()`: the options (interfaces.md),
// the request they make, the command up to its outputs, and the result as
// columns (the CSV's, also handed to Python as arrays).
#pragma once
#include <cstdint>
#include <ostream>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "sizing/option_table.hpp"
#include "sizing/sweep.hpp"

namespace sreh::sizing {

struct SweepOptions {
  std::vector<double> loads_gcm2, angles_deg, voltages_V{SupplySpec{}.voltage_V}, speeds_dps, targets_s;
  double accel_pct = 100.0, jerk_pct = 100.0;
  // Defaults: the world's and the settling spec's, never retyped.
  double dwell_s = 0.0, tolerance_deg = SettlingSpec{}.tolerance_deg, wait_ms = SettlingSpec{}.wait_ms,
         ambient_C = ThermalSpec{}.ambient_C;
  std::optional<double> timeout_ms;
  int cycles = 2;
  int threads = 0; // 0: io::default_threads (the CPUs this process may use, SLURM_CPUS_PER_TASK if fewer)
  std::string csv, report;
  std::string shard; // "i/N", "auto", "auto/N"; "" runs the whole grid
  std::string model; // --model FILE: model card overrides (issue 25)
  bool uncertainty = false; // --uncertainty: _lo / _hi columns (issue 26)
  int samples = 32;
  int seed = 1;
};

// Every option of `sweep`; list options take comma-separated values on the CLI.
std::span<const OptionSpec<SweepOptions>> sweep_option_table();

// Throws SizingInputError (threads outside 1..64, a target time <= 0; the
// grid itself is checked by sweep_requests).
SweepRequest make_sweep_request(const SweepOptions& options);

// make_sweep_request + run_sweep + the CSV / report when asked (atomic
// writes). Throws SizingInputError for bad input (the CLI's exit 2).
SweepResult run_sweep_command(const SweepOptions& options, const SweepRequest& request);

// One column of the result: a number (empty CSV cell when missing), a 0/1
// flag, a count, a word (unquoted in the CSV) or a text (quoted), for every
// point in grid order.
enum class SweepColumnKind { Number, Flag, Count, Word, Text };
struct SweepColumnSpec {
  std::string_view name;
  SweepColumnKind kind;
};
using SweepCell = std::variant<std::monostate, double, bool, int64_t, std::string>; // monostate: missing
// With `uncertainty` also positioning_s_lo/_hi, settling_s_lo/_hi,
// peak_torque_Nm_lo/_hi, steady_temperature_C_lo/_hi, feasible_worst_case.
std::span<const SweepColumnSpec> sweep_columns(bool uncertainty = false);
SweepCell sweep_cell(const SweepPoint& point, std::size_t column);

} // namespace sreh::sizing
