#include "calibration/calibrate.hpp"

#include <cmath>

#include <fmt/format.h>

#include "calibration/fit_output.hpp"
#include "scenarios/load_file.hpp"
#include "twin/load_builder.hpp"
#include "scenarios/scenario_parser.hpp"

namespace sreh {
namespace {


LoadSpec load_of(const CalibrateRequest& r) {
  if (r.load_gcm2 && !r.load_file.empty()) throw CalibrationInputError("--load-gcm2 and --load: give only one of them");
  if (r.load_gcm2) {
    if (!std::isfinite(*r.load_gcm2) || *r.load_gcm2 < 0 || *r.load_gcm2 > max_load_gcm2()) {
      throw CalibrationInputError(fmt::format("--load-gcm2 {:g}: expected 0 .. {:g} g cm^2 (manual 3.5.6)", *r.load_gcm2,
                                              max_load_gcm2()));
    }
    return InertiaLoad{*r.load_gcm2};
  }
  if (!r.load_file.empty()) {
    try {
      return parse_load_file(r.load_file).load;
    } catch (const ScenarioError& e) {
      throw CalibrationInputError(fmt::format("--load {}", e.what()));
    }
  }
  throw CalibrationInputError("calibrate: give the attached load with --load-gcm2 J or --load LOAD.yaml");
}

} // namespace

CalibrateInputs read_calibrate_inputs(const CalibrateRequest& request) {
  if (request.logs.empty()) throw CalibrationInputError("calibrate: give at least one master log (LOG.csv)");
  CalibrateInputs in;
  const LoadSpec load = load_of(request);
  std::optional<Scenario> setup;
  if (!request.setup.empty()) {
    try {
      setup = parse_scenario_file(request.setup);
    } catch (const ScenarioError& e) {
      throw CalibrationInputError(fmt::format("--setup {}", e.what()));
    }
  }
  try {
    in.start = request.model.empty() ? default_model_card() : apply_model_file(default_model_card(), request.model);
  } catch (const ModelCardError& e) {
    throw CalibrationInputError(fmt::format("--model {}", e.what()));
  }
  for (const std::string& path : request.logs) {
    FitCase c;
    c.log = read_master_log(path);
    c.setup = replay_setup(c.log, load, setup ? &*setup : nullptr);
    in.cases.push_back(std::move(c));
  }
  return in;
}

CalibrateOutcome calibrate(const CalibrateRequest& request) {
  CalibrateInputs in = read_calibrate_inputs(request);
  FitOptions options = request.options;
  options.names = request.fit;
  // Names are checked before the first replay (exit 2 before long work).
  CalibrateOutcome out;
  out.start = in.start;
  out.fit = fit_model(in.cases, in.start, options);
  out.model_yaml = fit_model_yaml(out.fit, default_model_card(), request.logs, calibration_date());
  out.cases = std::move(in.cases);
  return out;
}

} // namespace sreh
