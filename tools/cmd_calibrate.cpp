// `sreh-twin calibrate LOG.csv... (--load-gcm2 L | --load FILE) --out FIT.yaml`
// (issue 26): fit model-card constants to master logs of a real module
// (calibration/), and `calibrate --plan OUT.yaml`: the identification
// program to record them with. Exit 0 converged, 1 not converged or the
// residual too large, 2 bad input (a log named by file:line).
#include <unistd.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <sstream>

#include <fmt/format.h>

#include "calibration/calibrate.hpp"
#include "calibration/fit_output.hpp"
#include "calibration/plan.hpp"
#include "calibration/plan_sensitivity.hpp"
#include "calibration/report.hpp"
#include "io/atomic_file.hpp"
#include "io/cpus.hpp"
#include "io/output_path.hpp"
#include "scenarios/load_file.hpp"
#include "scenarios/scenario_parser.hpp"
#include "tools/command.hpp"
#include "tools/progress.hpp"

namespace sreh::tools {
namespace {

struct CalibrateArgs {
  CalibrateRequest request;
  std::optional<double> load_gcm2;
  std::string fit;  // NAME,NAME
  std::string out;
  std::string report; // --report DIR
  std::string plan;   // --plan OUT.yaml
  double mounting_tilt_deg = 0;
  bool json = false;
  bool quiet = false; // no progress lines on stderr
};

std::vector<std::string> split_names(const std::string& list) {
  std::vector<std::string> names;
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');) {
    if (name.empty()) throw InputError(fmt::format("--fit {}: an empty name", list));
    names.push_back(name);
  }
  return names;
}

std::vector<std::string> inputs_of(const CalibrateArgs& a) {
  std::vector<std::string> in = a.request.logs;
  for (const std::string* f : {&a.request.load_file, &a.request.setup, &a.request.model}) {
    if (!f->empty()) in.push_back(*f);
  }
  return in;
}

int plan_command(const CalibrateArgs& a) {
  if (!a.request.logs.empty() || !a.out.empty() || !a.report.empty()) {
    throw InputError("--plan: writes a scenario; give no logs, no --out and no --report");
  }
  io::check_outputs({{"--plan", a.plan, io::OutputKind::File}}, inputs_of(a));
  PlanRequest p;
  p.load_gcm2 = a.request.load_gcm2;
  p.load_file = a.request.load_file;
  p.mounting_tilt_deg = a.mounting_tilt_deg;
  std::string text;
  try {
    text = calibration_plan_yaml(p);
  } catch (const CalibrationInputError& e) {
    throw InputError(e.what());
  }
  // What each move shows (issue 36), measured before anything is written:
  // a --model that does not read is refused with the plan unwritten.
  ModelCard card;
  try {
    card = a.request.model.empty() ? default_model_card() : apply_model_file(default_model_card(), a.request.model);
  } catch (const ModelCardError& e) {
    throw InputError(fmt::format("--model {}", e.what()));
  }
  std::vector<std::string> names = default_fit_names();
  names.insert(names.end(), {"rotor_inertia", "torque_constant", "winding_resistance", "velocity_bandwidth",
                             "position_ratio", "integral_ratio"});
  const PlanSensitivity shows =
      plan_sensitivity(parse_scenario_text(text, a.plan, ""), card, names, std::max(1, io::usable_cpus()));
  io::write_file_atomic(a.plan, [&](std::ostream& out) { out << text; });
  std::cout << "wrote " << a.plan << " (the identification program: run it on the module with the master logging, "
            << "then calibrate the logs with --setup " << a.plan << ")\n"
            << format_plan_sensitivity(shows)
            << "The default fit is the first five; the others with --fit NAME,... (docs/calibration.md).\n";
  return 0;
}

int calibrate_command(CalibrateArgs a) {
  a.request.load_gcm2 = a.load_gcm2;
  if (!a.plan.empty()) return plan_command(a);
  if (a.out.empty()) throw InputError("calibrate: give --out FIT.yaml (or --plan OUT.yaml for the identification program)");
  if (!a.fit.empty()) a.request.fit = split_names(a.fit);
  if (!a.report.empty() && !calibration_reports_available()) throw InputError("--report: this build has no renders");
  io::check_outputs({{"--out", a.out, io::OutputKind::File}, {"--report", a.report, io::OutputKind::Folder}}, inputs_of(a));
  CalibrateOutcome outcome;
  // Progress on stderr (issue 29): a fit replays the logs dozens of times.
  Progress progress(isatty(STDERR_FILENO) != 0, a.quiet);
  progress.phase("fitting");
  a.request.options.progress = [&progress](int iterations, int max_iterations) {
    progress.update(std::min(0.99, static_cast<double>(iterations) / max_iterations));
  };
  try {
    outcome = calibrate(a.request);
    progress.end_phase();
  } catch (const CalibrationInputError& e) {
    throw InputError(e.what());
  } catch (const std::invalid_argument& e) { // a load or setup the twin rejects
    throw InputError(e.what());
  }
  io::write_file_atomic(a.out, [&](std::ostream& out) { out << outcome.model_yaml; });
  const FitResult& fit = outcome.fit;
  if (!a.report.empty()) write_calibration_report(a.report, outcome.cases, outcome.start, fit);
  if (a.json) {
    std::cout << fit_json(fit).dump(2) << "\n";
  } else {
    std::cout << fmt::format("{} after {} iterations from {} starts: rms residual {:.5f} deg (start {:.5f} deg; the log's "
                             "floor {:.5f} deg, {:.2f} counts of noise), {} logged rows\n",
                             fit.converged ? "converged" : "NOT converged", fit.iterations, fit.starts, fit.rms_residual_deg,
                             fit.start_rms_residual_deg, fit.floor_rms_deg, fit.noise_counts, fit.residuals);
    if (!fit.adequate) std::cout << fit.inadequacy << "\n";
    std::size_t name_width = 22; // the card's longest names (the thermal ones) still line up
    for (const FittedConstant& f : fit.constants) name_width = std::max(name_width, f.name.size());
    for (const FittedConstant& f : fit.constants) {
      std::cout << fmt::format("  {:<{}} {:>12.6g} {:<10} ({} {:.6g}, 95 % [{:.6g}, {:.6g}]){}\n", f.name, name_width, f.value,
                               f.unit, f.load ? "stated" : "start", f.start, f.ci95_lo, f.ci95_hi,
                               f.identified ? "" : "  not identified: " + f.note);
    }
    for (const std::string& note : fit.notes) std::cout << "  note: " << note << "\n";
    std::cout << "wrote " << a.out << (a.report.empty() ? "" : " and " + a.report + "/index.html") << "\n";
  }
  if (!fit.adequate && !a.json) std::cerr << "calibrate: " << fit.inadequacy << "\n";
  return fit.converged && fit.adequate ? 0 : 1;
}

} // namespace

SREH_REGISTER_COMMAND(57, [](CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CalibrateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "calibrate", "Fit the model card's constants to master logs of a real module, or write the identification "
                   "program (--plan); exit 0 converged, 1 not converged or the model does not explain the log (its rms "
                   "residual over 3x the log's floor), 2 bad input (docs/calibration.md)");
  CalibrateRequest& r = args->request;
  cmd->add_option("logs", r.logs, "Master logs (t_s,pd_out,pd_in[,temperature_C]: `run --master-log`)");
  cmd->add_option("--load-gcm2", args->load_gcm2, "The attached load's inertia about the axis, g cm^2");
  cmd->add_option("--load", r.load_file, "The attached load as a load file (scenario `load:` syntax)");
  cmd->add_option("--setup", r.setup,
                  "The scenario the logs were recorded with (e.g. the --plan): its world and start-up ISDU writes "
                  "(device.isdu), which a process-data log does not carry");
  cmd->add_option("--model", r.model, "Start from this model file (default: the model card)");
  cmd->add_option("--fit", args->fit,
                  "Constants to fit, NAME,NAME... [default: coulomb_friction,viscous_friction,stribeck_excess,"
                  "torsional_stiffness,torsional_damping; and winding_heat_capacity,winding_to_housing_resistance "
                  "on a log whose polled temperature rises >= 2 degC over the winding's time constant]. `load` (or "
                  "`load_inertia`) fits the attached load's inertia too, from the stated --load-gcm2/--load (named "
                  "alone: with the default constants); it is reported against the stated load, not written to --out");
  cmd->add_option("--out", args->out, "Write the fitted model file here (what --model reads)");
  cmd->add_option("--report", args->report,
                  "Write an HTML report into this folder: logged vs simulated position and error per log (start and "
                  "fitted card), the constants with their intervals, the correlation");
  cmd->add_flag("--json", args->json, "Print {constants: {NAME: {value, start, ci95}}, rms_residual_deg, iterations, converged}");
  cmd->add_option("--threads", r.options.threads, "Replays in parallel [default: the CPUs this process may use]")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--max-iterations", r.options.max_iterations, "Solver iterations at most")
      ->check(CLI::Range(1, 1000))->capture_default_str();
  cmd->add_option("--max-rms-deg", r.options.max_rms_residual_deg, "A fit with a larger rms residual is not converged (exit 1)")
      ->check(CLI::Range(0.0, 360.0))->capture_default_str();
  cmd->add_option("--step", r.options.relative_step, "Finite-difference step, fraction of each start value (A-CAL-3)")
      ->check(CLI::Range(1e-4, 0.5))->capture_default_str();
  cmd->add_option("--starts", r.options.starts,
                  "Solver starts: the start card, and spread points of the ranges (the best goes on; a constant on "
                  "which they disagree is not identified)")
      ->check(CLI::Range(1, 16))->capture_default_str();
  cmd->add_option("--bootstrap", r.options.bootstrap,
                  "Refits of logs the fitted model records, from other starts: their spread is the intervals' "
                  "(0: the likelihood's interval alone)")
      ->check(CLI::Range(0, 16))->capture_default_str();
  cmd->add_option_function<double>(
         "--noise-counts", [args](double v) { args->request.options.noise_counts = v; },
         "The logged position's noise, wire counts (one sigma) [default: estimated from the log]")
      ->check(CLI::Range(0.0, 1000.0));
  cmd->add_flag("--quiet", args->quiet, "No progress lines on stderr (they come for work over 2 s)");
  cmd->add_option("--plan", args->plan, "Write the identification program (a scenario to run on the module) here");
  // The one range of the mounting tilt (issue 39): the world's, as in size and a scenario's mounting:.
  cmd->add_option("--mounting-tilt-deg", args->mounting_tilt_deg,
                  fmt::format("With --plan: tilt of the axis from vertical, {:g} .. {:g} deg (90 horizontal)",
                              kMinMountingTiltDeg, kMaxMountingTiltDeg))
      ->check(CLI::Range(kMinMountingTiltDeg, kMaxMountingTiltDeg));
  r.options.threads = io::usable_cpus();
  cmd->callback([args, &exit_code] { exit_code = calibrate_command(*args); });
});

} // namespace sreh::tools
