#include "calibration/fit.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "calibration/fit_cost.hpp"

namespace sreh {
namespace {

constexpr int kMaxSolves = 4;                  // restarts of the trust region
constexpr double kRestartGain = 0.01;          // a restart must lower the cost by 1 %
constexpr double kZ95 = 1.959963984540054;     // two-sided 95 % of the normal distribution
constexpr double kWideHalfWidth = 0.25;        // an interval wider than +-25 % of the value: not identified
constexpr double kStrongCorrelation = 0.95;    // |r| above this: the data cannot separate the two
// Logs longer than twice this are first fitted on their first kCoarse_s
// (shared out in proportion to their lengths; the plan is ~9 s), then on
// the whole from there (A-CAL-8).
constexpr double kCoarse_s = 10.0;

// Reports every solver iteration to FitOptions::progress, counting across
// the restarts and stages (iteration 0 of a solve is its start, not an iteration).
class IterationProgress final : public ceres::IterationCallback {
 public:
  IterationProgress(const FitOptions& options, const int& done_before) : options_(options), done_before_(done_before) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (s.iteration > 0) options_.progress(done_before_ + s.iteration, options_.max_iterations);
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const FitOptions& options_;
  const int& done_before_; // iterations of the earlier solves
};

// Ends a solve where the step still ahead is within the noise (A-CAL-8):
// the Gauss-Newton step d from the best point so far, kept inside the
// bounds, measured in the constants' covariance C (A-CAL-4), d^T C^-1 d,
// is at most the number of constants n, what fitting n constants to pure
// noise gains on average. Further steps only chase the replay's
// count-sized roughness. Ceres writes its best point into the parameter
// block every iteration and has just taken the Jacobian there when that
// point is new, so the test costs no replay.
class WithinNoise final : public ceres::IterationCallback {
 public:
  WithinNoise(const std::vector<FitCase>& cases, const ReplayCost& cost, const Unknowns& u, const double* x)
      : cases_(cases), cost_(cost), u_(u), x_(x) {}
  double distance2() const { return distance2_; }
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (!s.step_is_successful) return ceres::SOLVER_CONTINUE;
    const std::vector<double>* jacobian = cost_.jacobian_at(x_);
    if (!jacobian) return ceres::SOLVER_CONTINUE;
    const std::size_t n = u_.card_index.size();
    const Covariance c = covariance_at(cases_, cost_.jacobian_residuals(), *jacobian, n);
    if (c.singular) return ceres::SOLVER_CONTINUE;
    Eigen::VectorXd step(static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) {
      const auto k = static_cast<Eigen::Index>(i);
      step(k) = std::clamp(x_[i] + c.gauss_newton(k), u_.lo[i], u_.hi[i]) - x_[i];
    }
    distance2_ = step.dot(c.cov.completeOrthogonalDecomposition().solve(step));
    return distance2_ <= static_cast<double>(n) ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }

 private:
  const std::vector<FitCase>& cases_;
  const ReplayCost& cost_;
  const Unknowns& u_;
  const double* x_; // the parameter block, updated every iteration
  double distance2_ = 0;
};

struct Stage {
  std::unique_ptr<ReplayCost> cost;
  ceres::Solver::Summary summary;
  bool converged = false; // Ceres' tolerances or the noise test
};

// Solves `cases` from x (updated in place), restarted while that pays
// (A-CAL-3); `iterations` counts on across stages.
Stage solve(const std::vector<FitCase>& cases, const ModelCard& start, const Unknowns& u, std::vector<double>& x,
            const FitOptions& options, int& iterations) {
  const std::size_t n = x.size();
  Stage stage;
  stage.cost = std::make_unique<ReplayCost>(cases, start, u, options.threads, options.relative_step);
  ceres::Problem::Options po;
  po.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP; // read after the solve
  ceres::Problem problem(po);
  problem.AddResidualBlock(stage.cost.get(), nullptr, x.data());
  for (std::size_t i = 0; i < n; ++i) {
    problem.SetParameterLowerBound(x.data(), static_cast<int>(i), u.lo[i]);
    problem.SetParameterUpperBound(x.data(), static_cast<int>(i), u.hi[i]);
  }
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = options.max_iterations;
  so.logging_type = ceres::SILENT;
  so.minimizer_progress_to_stdout = false;
  so.function_tolerance = 1e-6;
  so.parameter_tolerance = 1e-5;
  so.num_threads = 1; // the replays are parallel already
  // The cost of a closed-loop replay is rough at the scale of an encoder
  // count: non-monotonic steps let the trust region step over a local dip,
  // and a fresh solve from the result restores a trust region that shrank
  // on the roughness, as long as that still lowers the cost by 1 % (A-CAL-3).
  so.use_nonmonotonic_steps = true;
  // With bounds Ceres refines each trust-region step by a line search; its
  // default cubic interpolation asks for the gradient, a whole Jacobian of
  // 2n replays, at every trial step size. Quadratic interpolation needs the
  // cost only, one replay per trial (A-CAL-8).
  so.line_search_interpolation_type = ceres::QUADRATIC;
  so.update_state_every_iteration = true; // WithinNoise reads x
  WithinNoise within_noise(cases, *stage.cost, u, x.data());
  so.callbacks.push_back(&within_noise);
  IterationProgress progress(options, iterations);
  if (options.progress) so.callbacks.push_back(&progress);
  for (int attempt = 0; attempt < kMaxSolves; ++attempt) {
    ceres::Solve(so, &problem, &stage.summary);
    iterations += static_cast<int>(stage.summary.iterations.size()) - 1;
    if (stage.summary.termination_type != ceres::CONVERGENCE ||
        !(stage.summary.final_cost < (1 - kRestartGain) * stage.summary.initial_cost)) {
      break;
    }
  }
  stage.converged = stage.summary.termination_type == ceres::CONVERGENCE ||
                    stage.summary.termination_type == ceres::USER_SUCCESS;
  if (stage.summary.termination_type == ceres::USER_SUCCESS) {
    stage.summary.message = fmt::format("the step still ahead is within the noise (d^2 = {:.2f} <= {} constants, A-CAL-8)",
                                        within_noise.distance2(), n);
  }
  return stage;
}

// The first kCoarse_s of the logs, shared out in proportion to their
// lengths; empty when the logs are not longer than twice that.
std::vector<FitCase> coarse_cases(const std::vector<FitCase>& cases) {
  double total_s = 0;
  for (const FitCase& c : cases) total_s += static_cast<double>(c.log.rows.size()) * c.setup.config.cycle_s;
  if (total_s <= 2 * kCoarse_s) return {};
  std::vector<FitCase> coarse = cases;
  for (FitCase& c : coarse) {
    const auto rows = static_cast<std::size_t>(std::ceil(static_cast<double>(c.log.rows.size()) * kCoarse_s / total_s));
    c.log.rows.resize(std::max<std::size_t>(rows, 2));
  }
  return coarse;
}

} // namespace

std::vector<std::string> default_fit_names() {
  return {"coulomb_friction", "viscous_friction", "stribeck_excess", "torsional_stiffness", "torsional_damping"};
}

DefaultFit default_fit(const std::vector<FitCase>& cases, const ModelCard& start) {
  DefaultFit d{default_fit_names(), ""};
  const double time_constant_s =
      start.find("winding_heat_capacity")->value * start.find("winding_to_housing_resistance")->value;
  double best_span_C = 0; // of the logs long enough
  double longest_s = 0;
  bool polled = false;
  for (const FitCase& c : cases) { // per log: two logs at different ambients are no heating
    double lo = INFINITY;
    double hi = -INFINITY;
    for (const MasterLogRow& row : c.log.rows) {
      if (!row.temperature_C) continue;
      polled = true;
      lo = std::min(lo, *row.temperature_C);
      hi = std::max(hi, *row.temperature_C);
    }
    if (hi < lo || c.log.rows.size() < 2) continue;
    const double thermal_s = (c.log.rows.back().t_s - c.log.rows.front().t_s) * c.setup.config.thermal.time_scale;
    longest_s = std::max(longest_s, thermal_s);
    if (thermal_s >= time_constant_s) best_span_C = std::max(best_span_C, hi - lo);
  }
  if (!polled) return d;
  if (best_span_C >= kThermalFitSpan_C) {
    d.names.insert(d.names.end(), {"winding_heat_capacity", "winding_to_housing_resistance"});
  } else if (longest_s < time_constant_s) {
    d.note = fmt::format("thermal constants not fitted: the longest log lasts {:.0f} s of the winding's {:.0f} s "
                         "time constant (a longer log; --fit names them anyway)",
                         longest_s, time_constant_s);
  } else {
    d.note = fmt::format("thermal constants not fitted: the polled temperature spans {:.1f} degC, a fit needs "
                         "{:.0f} degC of heating (a busier log; --fit names them anyway)",
                         best_span_C, kThermalFitSpan_C);
  }
  return d;
}

std::vector<double> position_residuals_deg(const std::vector<FitCase>& cases, const ModelCard& card) {
  std::vector<double> r(position_count(cases));
  residuals_into(cases, card, r.data(), false);
  return r;
}

FitResult fit_model(const std::vector<FitCase>& cases, const ModelCard& start, const FitOptions& options) {
  const DefaultFit by_default = options.names.empty() ? default_fit(cases, start) : DefaultFit{};
  const std::vector<std::string> names = options.names.empty() ? by_default.names : options.names;
  const Unknowns u = unknowns_of(start, names);
  const std::size_t n = names.size();
  std::vector<double> x(n, 1.0);
  for (std::size_t i = 0; i < n; ++i) x[i] = std::clamp(start.constants[u.card_index[i]].value / u.scale[i], u.lo[i], u.hi[i]);

  FitResult result;
  result.residuals = position_count(cases);
  result.temperature_residuals = u.temperature ? temperature_count(cases) : 0;
  result.start_rms_residual_deg = rms(position_residuals_deg(cases, start));
  result.replays = 1;
  if (!by_default.note.empty()) result.notes.push_back(by_default.note);

  int iterations = 0;
  if (const std::vector<FitCase> coarse = coarse_cases(cases); !coarse.empty()) {
    const Stage first = solve(coarse, start, u, x, options, iterations);
    result.replays += first.cost->replays();
  }
  const Stage stage = solve(cases, start, u, x, options, iterations);

  // The Jacobian and residuals at the solution, for the intervals (taken
  // already where the solve ended on the noise test).
  const std::size_t positions = result.residuals;
  const std::size_t m = positions + result.temperature_residuals;
  std::vector<double> r(m), jac(m * n);
  const double* params[] = {x.data()};
  double* jacs[] = {jac.data()};
  stage.cost->Evaluate(params, r.data(), jacs);
  result.replays += stage.cost->replays();
  const Covariance cv = covariance_at(cases, r, jac, n);
  const auto split = r.begin() + static_cast<std::ptrdiff_t>(positions);
  result.rms_residual_deg = rms(std::vector<double>(r.begin(), split));
  result.rms_temperature_residual_C = rms(std::vector<double>(split, r.end())) / kTemperatureWeight_deg_per_C;
  result.autocorrelation_rows = cv.autocorrelation_rows;
  result.iterations = iterations;
  result.solver_message = stage.summary.message;
  result.converged = stage.converged && result.rms_residual_deg <= options.max_rms_residual_deg;
  result.card = card_at(start, u, x.data());
  const Eigen::MatrixXd& cov = cv.cov;
  const bool singular = cv.singular;
  result.correlation.assign(n, std::vector<double>(n, 0.0));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      const double d = std::sqrt(cov(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i)) *
                                 cov(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(j)));
      result.correlation[i][j] = d > 0 ? cov(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) / d : 0.0;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const ModelConstant& c = result.card.constants[u.card_index[i]];
    FittedConstant f;
    f.name = c.name;
    f.unit = c.unit;
    f.value = c.value;
    f.start = start.constants[u.card_index[i]].value;
    const double half = kZ95 * std::sqrt(std::max(0.0, cov(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i)))) *
                        u.scale[i];
    f.ci95_lo = f.value - half;
    f.ci95_hi = f.value + half;
    if (singular || half == 0) {
      f.identified = false;
      f.note = "the data do not move the position: no interval";
    } else if (half > kWideHalfWidth * std::abs(f.value)) {
      f.identified = false;
      f.note = fmt::format("wide interval: +-{:.0f} % of the value", 100 * half / std::abs(f.value));
    }
    for (std::size_t j = 0; j < n && f.identified; ++j) {
      if (j != i && std::abs(result.correlation[i][j]) > kStrongCorrelation) {
        f.identified = false;
        f.note = fmt::format("correlated with {} (r = {:.2f})", names[j], result.correlation[i][j]);
      }
    }
    result.constants.push_back(f);
  }
  return result;
}

} // namespace sreh
