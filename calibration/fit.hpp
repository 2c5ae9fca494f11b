// The fit (issue 26): model-card constants by bounded nonlinear least
// squares on the logged encoder position (Ceres' trust region, A-CAL-3),
// every residual a replay of a master log through the twin
// (calibration/replay.hpp). 95 % intervals from the Jacobian at the
// solution, widened for the residuals' autocorrelation (A-CAL-4).
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "calibration/replay.hpp"
#include "twin/model_card.hpp"

namespace sreh {

// |r| above this: the data cannot separate two fitted constants; the fit
// flags them (A-CAL-4) and the report shows r in bold.
inline constexpr double kStrongCorrelation = 0.95;

struct FitCase {
  MasterLog log;
  ReplaySetup setup;
};

// Refits of the bootstrap by default (A-CAL-12): three distances, the t
// distribution's 95 % multiple 3.18 (four would give 2.78 at a third more
// of the bootstrap's CPU: each refit is a whole fit of the log, or of a
// long log's first 10 s).
inline constexpr int kDefaultBootstrap = 3;

struct FitOptions {
  // Constants to fit (empty: default_fit(cases, start)); "load" or
  // "load_inertia" fits the attached load too, and named alone, with the
  // default constants (A-CAL-14).
  std::vector<std::string> names;
  int threads = 2;                // replays run in parallel (finite differences)
  int max_iterations = 25;
  // Central-difference step, in units of the start value: wide enough to
  // step over the count-sized jitter of a closed-loop replay on a quantised
  // encoder, small against the card's ranges (A-CAL-3).
  double relative_step = 0.1;
  double max_rms_residual_deg = 0.02; // converged but worse than this: not a fit (exit 1)
  // Starts (issue 36): the start card, solved to convergence, and
  // starts - 1 points spread over the ranges, spread_start_iterations each;
  // the best goes on (A-CAL-8).
  int starts = 3;
  int spread_start_iterations = 8;
  // The logged position's noise, wire counts (one sigma), as stated by the
  // user; unset: estimated from the log (calibration/fit_adequacy.hpp).
  std::optional<double> noise_counts;
  // The bootstrap (A-CAL-12, calibration/fit_refit.hpp): `bootstrap` logs
  // the fitted model records (with a fresh draw of the log's noise each)
  // are fitted again, each from one start (the start card, then spread
  // points of the ranges) solved to convergence; their distances from the
  // fit widen each constant's interval. 0: none (the likelihood interval
  // alone).
  int bootstrap = kDefaultBootstrap;
  // The likelihood probes widening the intervals (A-CAL-4); off in the
  // bootstrap's own fits, which need the values only.
  bool likelihood_probes = true;
  // Called after every solver iteration with the iterations so far (over
  // the restarts) and max_iterations: the CLI's progress line (issue 29).
  std::function<void(int iterations, int max_iterations)> progress;
};

// A fitted constant of the card, or the attached load (`load`, --fit load,
// A-CAL-14): a quantity of the setup, not of the module, so never written
// into the model file; its start is the stated load, g cm^2.
struct FittedConstant {
  std::string name;
  std::string unit;
  double value = 0;
  double start = 0;
  double ci95_lo = 0;
  double ci95_hi = 0;
  bool identified = true;  // false: see note
  std::string note;         // why not identified
  bool at_bound = false;    // ends at a bound of its range
  bool starts_disagree = false;    // another start ended as well outside the curvature's interval
  bool likelihood_widened = false; // the interval was widened along the cost (A-CAL-4)
  // Before the bootstrap (A-CAL-12): the curvature's interval widened by
  // the likelihood probes and the starts; the bootstrap's interval (before
  // a constant not identified reports the card's range); and where its
  // refits landed.
  double likelihood_lo = 0, likelihood_hi = 0;
  double bootstrap_lo = 0, bootstrap_hi = 0;
  std::vector<double> refits{};
  double range_lo = 0, range_hi = 0; // the card's range (the load's: kLoadScaleLo .. kLoadScaleHi of the stated)
  bool load = false;
};

struct FitResult {
  std::vector<FittedConstant> constants;
  ModelCard card;                 // the start card with the fitted values
  // With the load fitted: each case's carried load over its stated one (1
  // for a case without a load); empty otherwise. with_fitted_load applies it.
  std::vector<double> load_scale;
  double rms_residual_deg = 0;
  double start_rms_residual_deg = 0;
  int iterations = 0;
  bool converged = false;         // the solver converged and the residual is small enough
  std::string solver_message;
  std::vector<std::vector<double>> correlation; // between the fitted constants
  std::size_t residuals = 0;      // logged rows used
  // Polled temperatures used (a thermal constant fitted, A-CAL-9) and their
  // rms residual, degC; 0 without.
  std::size_t temperature_residuals = 0;
  double rms_temperature_residual_C = 0;
  double autocorrelation_rows = 1; // integrated autocorrelation time of the residuals, rows (A-CAL-4)
  std::size_t replays = 0;         // replays the fit cost, of the coarse stage's first seconds and of the whole logs (A-CAL-8)
  std::vector<std::string> notes;  // what the user should know: e.g. why no thermal constant was fitted
  int starts = 1;                  // starts solved (A-CAL-8)
  // Adequacy (A-CAL-10): the rms a right model leaves on this log, from the
  // wire's quantisation and the noise (stated or estimated, counts).
  double noise_counts = 0;
  double floor_rms_deg = 0;
  bool adequate = true;            // rms within kInadequateRatio of the floor
  std::string inadequacy;          // when not: "the model does not explain this log: ..." with the segment
};

// What the data of a calibration plan identify by default: friction on the
// rotor (Coulomb, viscous, breakaway) and the drive train's spring and
// damper (servo.md "Identification"). Not the rotor inertia: the manual
// gives J_intern (3.5.4) and its card range is +-5 %, inside what it
// trades off against stiffness (A-CAL-7).
std::vector<std::string> default_fit_names();

// Issue 26: "thermal ones when a temperature column is present". The
// winding's heat capacity and its resistance to the housing join the
// default when one log lets them be told apart: its polled temperatures
// span at least kThermalFitSpan_C (four steps of index 112, manual 6.4)
// and it lasts at least the winding's time constant (C R of `start`, on
// the log's thermal clock); a shorter heating is a straight line whose
// slope gives only their product. Otherwise `note` says why they are left
// out (A-CAL-9). The housing's constants need hours: named only.
inline constexpr double kThermalFitSpan_C = 2.0;
struct DefaultFit {
  std::vector<std::string> names;
  std::string note; // why the thermal constants are left out ("" when fitted or no temperatures polled)
};
DefaultFit default_fit(const std::vector<FitCase>& cases, const ModelCard& start);

// Throws CalibrationInputError for a name not on the card or one whose range
// is a single value (nothing to fit).
FitResult fit_model(const std::vector<FitCase>& cases, const ModelCard& start, const FitOptions& options);

// The residuals (simulated - logged position, degrees) of one card on the
// cases, each case's load scaled by `load_scale` (a fit's; empty: as stated).
std::vector<double> position_residuals_deg(const std::vector<FitCase>& cases, const ModelCard& card,
                                           const std::vector<double>& load_scale = {});

// The cases with the load a fit found (FitResult::load_scale) in place of the stated one.
std::vector<FitCase> with_fitted_load(std::vector<FitCase> cases, const std::vector<double>& load_scale);

} // namespace sreh
