// `sreh-twin size` and `sreh_twin.size()`: the options (interfaces.md), how
// they become a SizingRequest, and the command itself up to its JSON object.
#pragma once
#include <functional>
#include <optional>
#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "scenarios/load_file.hpp"
#include "sizing/cycle.hpp"
#include "sizing/option_table.hpp"
#include "sizing/sizing.hpp"

namespace sreh::sizing {

struct SizeOptions {
  std::optional<double> angle_deg; // required unless --cycle
  std::optional<double> load_gcm2;
  std::string load;          // --load LOAD.yaml
  // Defaults: the world's and the settling spec's, never retyped.
  double voltage_V = SupplySpec{}.voltage_V;
  double dwell_s = 0.0;
  double tolerance_deg = SettlingSpec{}.tolerance_deg;
  double wait_ms = SettlingSpec{}.wait_ms;
  std::optional<double> timeout_ms;
  double ambient_C = ThermalSpec{}.ambient_C;
  std::optional<double> speed_dps, accel_pct, jerk_pct;
  int parameter_set = 1;
  int cycles = 2;
  double thermal_margin_K = 5.0;
  std::optional<double> max_positioning_ms, max_cycle_ms;
  double source_resistance_ohm = SupplySpec{}.source_resistance_ohm;
  double bus_capacitance_F = SupplySpec{}.bus_capacitance_F;
  int handshake_cycles = 4;
  std::optional<double> mounting_tilt_deg;
  std::string report;        // HTML report folder ("" none)
  std::string cycle;         // --cycle FILE.yaml: a multi-segment cycle (the file holds load, supply, ...)
  std::string emit_scenario; // --emit-scenario FILE: a scenario replaying the sized cycle
  std::string csv;           // --csv FILE: the figures of the JSON object, one a row (size_csv.hpp)
  std::string model;         // --model FILE: model card overrides (issue 25)
  bool uncertainty = false;  // --uncertainty: bands over the model card's ranges (issue 26)
  int samples = 32;          // --samples: models sampled (Latin hypercube)
  int seed = 1;              // --seed: of the sampling
  std::function<void()> on_simulation; // not an option: SizingRequest::on_simulation
  int settling_spread_counts = 4; // --settling-spread-counts: targets +-N counts around the answer (issue 35); 0 off
};

// Every option of `size` except the CLI's own --json.
std::span<const OptionSpec<SizeOptions>> size_option_table();

// A load file is YAML with a top-level `load:` key, exactly as in a scenario
// (scenarios/README.md); a scenario file works too (only its load is used).
// Throws SizingInputError naming `option` and the file.
LoadSpec load_from_file(const std::string& path, std::string_view option = "--load");

// The load and, when the file has a `mounting:` key (the scenario's
// {axis: vertical|horizontal} | {tilt_deg: T}), the axis tilt from vertical.
LoadFileContents read_load_file(const std::string& path, std::string_view option = "--load");

// Throws SizingInputError (no load given, both given, a bad load file).
SizingRequest make_request(const SizeOptions& options);

struct SizeOutcome {
  SizingRequest request;
  SizingResult result;
  std::optional<CycleRequest> cycle; // with --cycle: the cycle, and its result below
  CycleResult cycle_result;
  bool feasible = false;
  nlohmann::json json; // the `size --json` object
  std::string text;    // the summary of `size` without --json
};

// make_request + size (or, with --cycle, parse_cycle_file + size_cycle) +
// the report and the emitted scenario when asked; throws SizingInputError
// for bad input (the CLI's exit 2).
SizeOutcome run_size(const SizeOptions& options);

} // namespace sreh::sizing
