#include "sizing/size_options.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "device_logic/parameter_ids.hpp"
#include "io/atomic_file.hpp"
#include "io/output_path.hpp"
#include "scenarios/load_file.hpp"
#include "twin/load_builder.hpp"
#include "scenarios/scenario_parser.hpp"
#include "sizing/cycle_output.hpp"
#include "sizing/output.hpp"
#include "sizing/report.hpp"
#include "sizing/report_provenance.hpp"
#include "sizing/size_csv.hpp"
#include "sizing/settling_spread.hpp"
#include "sizing/uncertainty.hpp"
#include "io/cpus.hpp"
#include "io/figures.hpp"

namespace sreh::sizing {
namespace {

// The ranges in the help are the parameter table's rows (manual 6.2),
// formatted once, never retyped.
std::string row_range(ParamId row) { return fmt::format("{} .. {}", display_min(row), display_max(row)); }
const param::MotionSet kSet(0);
const std::string kLoadHelp =
    fmt::format("Load inertia about the axis, 0 .. {} g cm^2 [default: 0 unless --load]", max_load_gcm2());
const std::string kVoltageHelp = fmt::format("Motor supply {} .. {} V (index 85)", min_voltage_V(), max_voltage_V());
const std::string kSpeedHelp =
    fmt::format("Evaluate this speed, {} deg/s [default: recommend a set]", row_range(kSet.speed));
const std::string kAccelHelp =
    fmt::format("Evaluate this acceleration, {} % [default: recommended]", row_range(kSet.acceleration));
const std::string kJerkHelp = fmt::format("Evaluate this jerk, {} % [default: recommended]", row_range(kSet.jerk));
const std::string kTiltHelp =
    fmt::format("Axis tilt from vertical, {:g} .. {:g} deg (90 horizontal: gravity acts); default: the load file's mounting:, else 0",
                kMinMountingTiltDeg, kMaxMountingTiltDeg);
const std::string kSetHelp = fmt::format("Parameter set 0 .. {} (index 64 + n)", param::kMotionSets - 1);

using S = SizeOptions;
const OptionSpec<S> kSizeOptions[] = {
    {"angle-deg", "Move angle in degrees (the cycle is 0 -> A -> 0); required unless --cycle", &S::angle_deg},
    {"load-gcm2", kLoadHelp, &S::load_gcm2},
    {"load", "Load file: YAML with a 'load:' key as in a scenario", &S::load},
    {"voltage-V", kVoltageHelp, &S::voltage_V, false, true},
    {"dwell-s", "Pause after each move, s", &S::dwell_s, false, true},
    {"tolerance-deg", "Position tolerance in deg (index 64+n.5)", &S::tolerance_deg, false, true},
    {"wait-ms", "Waiting time in the window in ms (index 64+n.6)", &S::wait_ms, false, true},
    {"timeout-ms", "Settling timeout in ms (index 64+n.7) [default: wait + 75 ms, >= 100 ms]", &S::timeout_ms},
    {"ambient-C", "Ambient temperature 0 .. 50 degC", &S::ambient_C, false, true},
    {"speed-dps", kSpeedHelp, &S::speed_dps},
    {"accel-pct", kAccelHelp, &S::accel_pct},
    {"jerk-pct", kJerkHelp, &S::jerk_pct},
    {"parameter-set", kSetHelp, &S::parameter_set, false, true},
    {"cycles", "Back-and-forth cycles simulated, 1 .. 20", &S::cycles, false, true},
    {"thermal-margin-K", "Required margin below the 70 degC warning, K", &S::thermal_margin_K, false, true},
    {"max-positioning-ms", "Target: the gentlest set positioning within this time, ms", &S::max_positioning_ms},
    {"max-cycle-ms", "Target: the gentlest set whose cycle fits this time, ms", &S::max_cycle_ms},
    {"source-resistance-ohm", "Supply source resistance, ohm (0: ideal source)", &S::source_resistance_ohm, false, true},
    {"bus-capacitance-F", "Capacitance on the motor supply, F (with a source resistance)", &S::bus_capacitance_F, false, true},
    {"handshake-cycles", "IO-Link cycles per move for the PLC handshake (A-SIZE-16)", &S::handshake_cycles, false, true},
    {"mounting-tilt-deg", kTiltHelp, &S::mounting_tilt_deg},
    {"model", "Model card overrides (YAML as `sreh-twin model show` prints): the module's physical constants", &S::model},
    {"report", "Write an HTML sizing report into this folder", &S::report},
    {"uncertainty", "Also judge the answer on models sampled over the model card's ranges (--model narrows them), loop tuning "
                    "included: a searched set must be feasible in every sample; exit 0 only if the answer is feasible on the "
                    "nominal model and in every sample (a sample that does not complete is infeasible), else 1", &S::uncertainty},
    {"samples", "With --uncertainty: models sampled, 2 .. 1000 (Latin hypercube)", &S::samples, false, true},
    {"seed", "With --uncertainty: seed of the sampling (same seed, same answer)", &S::seed, false, true},
    {"settling-spread-counts", "Also run the answer with targets up to N position counts either side: median and p95 of the "
                               "settling where it changes by more than 1 ms, and whether the window is held; 0 .. 20, 0 off (not with --cycle)",
     &S::settling_spread_counts, false, true},
    {"cycle", "Size a multi-segment cycle from this YAML file (moves, dwells, load changes; docs/sizing.md)", &S::cycle},
    {"emit-scenario", "Write a scenario replaying the sized cycle in the twin to this file", &S::emit_scenario},
    {"csv", "Write the figures (those of --json) to this CSV file, one figure a row", &S::csv},
};

} // namespace

std::span<const OptionSpec<SizeOptions>> size_option_table() { return kSizeOptions; }

// The scenarios' load-file loader reads the file (issue 13: one loader), so
// keys, limits, errors and MJCF paths behave as in a scenario.
LoadSpec load_from_file(const std::string& path, std::string_view option) { return read_load_file(path, option).load; }

LoadFileContents read_load_file(const std::string& path, std::string_view option) {
  try {
    return parse_load_file(path);
  } catch (const ScenarioError& e) {
    throw SizingInputError(fmt::format("{} {}", option, e.what()));
  }
}

SizingRequest make_request(const SizeOptions& a) {
  SizingRequest rq;
  if (!a.angle_deg) throw SizingInputError("size: give the move with --angle-deg A, or a cycle with --cycle FILE.yaml");
  rq.angle_deg = *a.angle_deg;
  if (a.load_gcm2 && !a.load.empty()) throw SizingInputError("--load-gcm2 and --load: give only one of them");
  if (a.load_gcm2 && *a.load_gcm2 > 0 && *a.load_gcm2 < kMinInertiaGcm2) { // issue 29: name the option
    throw SizingInputError(fmt::format("--load-gcm2 {}: above 0 but below {} g cm^2, too small to model; give 0 for no load",
                                       *a.load_gcm2, kMinInertiaGcm2));
  }
  if (a.load_gcm2) rq.world.load = InertiaLoad{*a.load_gcm2};
  else if (!a.load.empty()) {
    LoadFileContents f = read_load_file(a.load);
    rq.world.load = std::move(f.load);
    const std::string file = std::filesystem::path(a.load).filename().string();
    rq.load_name = f.name.empty() ? file : fmt::format("{} ({})", f.name, file);
    rq.world.mounting_tilt_deg = f.mounting_tilt_deg.value_or(0.0);
  }
  else throw SizingInputError("size: give the load with --load-gcm2 J or --load LOAD.yaml");
  rq.world.supply.voltage_V = a.voltage_V;
  rq.dwell_s = a.dwell_s;
  rq.settling.tolerance_deg = a.tolerance_deg;
  rq.settling.wait_ms = a.wait_ms;
  rq.settling.timeout_ms = a.timeout_ms;
  rq.world.thermal.ambient_C = a.ambient_C;
  rq.parameter_set = a.parameter_set;
  rq.cycles = a.cycles;
  rq.thermal_margin_K = a.thermal_margin_K;
  rq.max_positioning_ms = a.max_positioning_ms;
  rq.max_cycle_ms = a.max_cycle_ms;
  rq.world.supply.source_resistance_ohm = a.source_resistance_ohm;
  rq.world.supply.bus_capacitance_F = a.bus_capacitance_F;
  rq.handshake_cycles = a.handshake_cycles;
  rq.on_simulation = a.on_simulation;
  if (a.mounting_tilt_deg) rq.world.mounting_tilt_deg = *a.mounting_tilt_deg;
  if (a.speed_dps || a.accel_pct || a.jerk_pct) {
    // Options left out keep the factory value of sets 1..7 (manual 6.2).
    const MotionSetting factory;
    rq.setting = MotionSetting{a.speed_dps.value_or(factory.speed_dps), a.accel_pct.value_or(factory.accel_pct),
                               a.jerk_pct.value_or(factory.jerk_pct)};
  }
  rq.world.module = module_from_option(a.model);
  if (!a.model.empty()) rq.world.model_file = std::filesystem::absolute(a.model).lexically_normal().string(); // --emit-scenario names it
  rq.keep_trace = !a.report.empty();
  return rq;
}

namespace {

// Options that describe the move, the load or the rig: with --cycle the
// cycle file holds them (one source of truth).
void refuse_with_cycle(const SizeOptions& a) {
  const SizeOptions d;
  const std::pair<bool, const char*> given[] = {
      {a.angle_deg.has_value(), "--angle-deg"}, {a.load_gcm2.has_value(), "--load-gcm2"}, {!a.load.empty(), "--load"},
      {a.speed_dps.has_value(), "--speed-dps"}, {a.accel_pct.has_value(), "--accel-pct"},
      {a.jerk_pct.has_value(), "--jerk-pct"},   {a.timeout_ms.has_value(), "--timeout-ms"},
      {a.max_positioning_ms.has_value(), "--max-positioning-ms"}, {a.max_cycle_ms.has_value(), "--max-cycle-ms"},
      {a.mounting_tilt_deg.has_value(), "--mounting-tilt-deg"}, {a.voltage_V != d.voltage_V, "--voltage-V"},
      {a.dwell_s != d.dwell_s, "--dwell-s"}, {a.tolerance_deg != d.tolerance_deg, "--tolerance-deg"},
      {a.wait_ms != d.wait_ms, "--wait-ms"}, {a.ambient_C != d.ambient_C, "--ambient-C"},
      {a.parameter_set != d.parameter_set, "--parameter-set"}, {a.cycles != d.cycles, "--cycles"},
      {a.thermal_margin_K != d.thermal_margin_K, "--thermal-margin-K"},
      {a.source_resistance_ohm != d.source_resistance_ohm, "--source-resistance-ohm"},
      {a.bus_capacitance_F != d.bus_capacitance_F, "--bus-capacitance-F"},
      {a.handshake_cycles != d.handshake_cycles, "--handshake-cycles"},
      {a.settling_spread_counts != d.settling_spread_counts, "--settling-spread-counts"}};
  for (const auto& [set, name] : given) {
    if (set) throw SizingInputError(fmt::format("{} with --cycle: give it in the cycle file (docs/sizing.md)", name));
  }
}

// The card the uncertainty samples: the model card with the world's model
// file (--model, or a cycle file's `model:`) applied, values and ranges.
ModelCard card_of(const WorldSetup& world) {
  return world.model_file.empty() ? default_model_card() : apply_model_file(default_model_card(), world.model_file);
}

SizeOutcome run_cycle(const SizeOptions& a) {
  refuse_with_cycle(a);
  SizeOutcome out;
  CycleRequest rq = parse_cycle_file(a.cycle);
  if (!a.model.empty()) { // the file's own `model:` or --model, not both (A-SCN-32)
    if (!rq.world.model_file.empty()) {
      throw SizingInputError(fmt::format("--model {}: the cycle file names its own model ({}); give one of them",
                                         a.model, rq.world.model_loc.str()));
    }
    rq.world.module = module_from_option(a.model);
    rq.world.model_file = std::filesystem::absolute(a.model).lexically_normal().string(); // --emit-scenario names it
  }
  rq.keep_trace = !a.report.empty();
  rq.threads = io::usable_cpus(); // the sets' searches side by side (issue 37); the same answer
  out.cycle_result = size_cycle(rq);
  std::optional<UncertaintyResult> u;
  if (a.uncertainty) {
    u = cycle_uncertainty(rq, plan_sets(rq), out.cycle_result.settings, card_of(rq.world), out.cycle_result.evaluation,
                          a.samples, static_cast<uint64_t>(a.seed), io::usable_cpus());
  }
  if (!a.report.empty()) {
    try {
      write_report_page(a.report, cycle_report_html(rq, out.cycle_result, u ? &*u : nullptr), cycle_provenance(rq));
    } catch (const std::runtime_error& e) {
      throw SizingInputError(fmt::format("--report {}: {}", a.report, e.what()));
    }
  }
  if (!a.emit_scenario.empty()) {
    const CyclePlan plan = plan_sets(rq);
    std::vector<int> set_of_segment;
    for (int k : plan.move_set) set_of_segment.push_back(k < 0 ? -1 : plan.sets[static_cast<std::size_t>(k)].set);
    write_scenario_file(a.emit_scenario,
                        scenario_yaml(rq, out.cycle_result.evaluation.sets, set_of_segment,
                                      "sized cycle " + std::filesystem::path(a.cycle).filename().string()));
  }
  // With --uncertainty the verdict over every sample (A-SIZE-UNC-2).
  out.feasible = u ? u->feasible_worst_case : out.cycle_result.evaluation.feasible;
  out.json = cycle_to_json(rq, out.cycle_result, u ? &*u : nullptr);
  io::round_figures(out.json); // issue 29: no float noise
  out.text = cycle_summary_text(rq, out.cycle_result, u ? &*u : nullptr);
  out.cycle = std::move(rq);
  return out;
}

} // namespace

namespace {

SizeOutcome run_size_or_cycle(const SizeOptions& a) {
  if (!a.report.empty() && !reports_available()) throw SizingInputError("--report: this build has no renders");
  try { // the one output rule, before any work (issue 12)
    io::check_outputs({{"--report", a.report, io::OutputKind::Folder},
                       {"--emit-scenario", a.emit_scenario, io::OutputKind::File},
                       {"--csv", a.csv, io::OutputKind::File}},
                      {a.load, a.cycle});
  } catch (const io::PathError& e) {
    throw SizingInputError(e.what());
  }
  if (a.uncertainty && (a.samples < 2 || a.samples > 1000)) {
    throw SizingInputError(fmt::format("--samples {}: expected 2 .. 1000", a.samples));
  }
  if (a.settling_spread_counts < 0 || a.settling_spread_counts > 20) {
    throw SizingInputError(fmt::format("--settling-spread-counts {}: expected 0 .. 20", a.settling_spread_counts));
  }
  if (!a.cycle.empty()) return run_cycle(a);
  SizeOutcome out;
  out.request = make_request(a);
  out.request.search_threads = io::usable_cpus(); // the gentlest search looks one candidate ahead (issue 37); the same answer
  std::optional<UncertaintyResult> u;
  if (a.uncertainty) { // the answer must hold in every sample (A-SIZE-UNC-3)
    UncertainSizing us = size_with_uncertainty(out.request, card_of(out.request.world), a.samples,
                                               static_cast<uint64_t>(a.seed), io::usable_cpus());
    out.result = std::move(us.result);
    u = std::move(us.uncertainty);
  } else {
    out.result = size(out.request);
  }
  std::optional<SettlingSpread> spread;
  if (a.settling_spread_counts > 0) {
    spread = settling_spread(out.request, out.result.evaluation.set, out.result.evaluation, a.settling_spread_counts,
                             io::usable_cpus());
    out.result.simulations += spread->simulations;
  }
  const AnswerExtras extras{u ? &*u : nullptr, spread ? &*spread : nullptr};
  if (!a.report.empty()) {
    try {
      write_report_page(a.report, size_report_html(out.request, out.result, extras.uncertainty, extras.spread),
                        size_provenance(out.request, out.result.evaluation.load_gcm2));
    } catch (const std::runtime_error& e) {
      throw SizingInputError(fmt::format("--report {}: {}", a.report, e.what()));
    }
  }
  if (!a.emit_scenario.empty()) {
    const CycleRequest c = cycle_of_single(out.request);
    write_scenario_file(a.emit_scenario,
                        scenario_yaml(c, {out.result.evaluation.set}, {out.request.parameter_set, -1, out.request.parameter_set, -1},
                                      fmt::format("sized move {} deg back and forth", out.request.angle_deg)));
  }
  // With --uncertainty the verdict over every sample (A-SIZE-UNC-2): the
  // exit code, JSON `feasible`, the text and the report's badge.
  out.feasible = u ? u->feasible_worst_case : out.result.feasible;
  out.json = to_json(out.request, out.result, extras);
  io::round_figures(out.json); // issue 29: no float noise
  out.text = summary_text(out.request, out.result, extras);
  return out;
}

} // namespace

SizeOutcome run_size(const SizeOptions& a) {
  SizeOutcome out = run_size_or_cycle(a);
  if (!a.csv.empty()) {
    try {
      io::write_file_atomic(a.csv, [&](std::ostream& f) { f << size_csv(out.json); });
    } catch (const std::runtime_error& e) {
      throw SizingInputError(fmt::format("--csv {}: {}", a.csv, e.what()));
    }
  }
  return out;
}

} // namespace sreh::sizing
