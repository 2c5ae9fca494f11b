#include "calibration/fit.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <ceres/ceres.h>
#include <fmt/format.h>

#include "io/parallel.hpp"

namespace sreh {
namespace {

// Forward-difference step, in units of the start value: wide enough to step
// over the encoder's count-sized jitter of a closed-loop replay, small
// against the card's ranges (A-CAL-3).
constexpr int kMaxSolves = 4;                  // restarts of the trust region
constexpr double kRestartGain = 0.01;          // a restart must lower the cost by 1 %
constexpr double kZ95 = 1.959963984540054;     // two-sided 95 % of the normal distribution
constexpr double kWideHalfWidth = 0.25;        // an interval wider than +-25 % of the value: not identified
constexpr double kStrongCorrelation = 0.95;    // |r| above this: the data cannot separate the two

struct Unknowns {
  std::vector<std::size_t> card_index; // into ModelCard::constants
  std::vector<double> scale;           // value = u * scale (the start value)
  std::vector<double> lo, hi;          // bounds on u
};

Unknowns unknowns_of(const ModelCard& start, const std::vector<std::string>& names) {
  Unknowns u;
  for (const std::string& name : names) {
    const ModelConstant* c = start.find(name);
    if (!c) throw CalibrationInputError(fmt::format("--fit {}: not a constant of the model card", name));
    if (!(c->range_hi > c->range_lo)) {
      throw CalibrationInputError(fmt::format("--fit {}: its range is the single value {:g}, nothing to fit", name, c->value));
    }
    if (std::find(u.card_index.begin(), u.card_index.end(), static_cast<std::size_t>(c - start.constants.data())) !=
        u.card_index.end()) {
      throw CalibrationInputError(fmt::format("--fit {}: named twice", name));
    }
    const double scale = c->value != 0 ? std::abs(c->value) : c->range_hi - c->range_lo;
    u.card_index.push_back(static_cast<std::size_t>(c - start.constants.data()));
    u.scale.push_back(scale);
    u.lo.push_back(c->range_lo / scale);
    u.hi.push_back(c->range_hi / scale);
  }
  return u;
}

ModelCard card_at(const ModelCard& start, const Unknowns& u, const double* x) {
  ModelCard card = start;
  for (std::size_t i = 0; i < u.card_index.size(); ++i) {
    auto& c = card.constants[u.card_index[i]];
    c.value = std::clamp(x[i] * u.scale[i], c.range_lo, c.range_hi);
  }
  return card;
}

// Replays every case with `card`, residuals appended in case order.
void residuals_into(const std::vector<FitCase>& cases, const ModelCard& card, double* out) {
  const ModuleModel module = card.module_model();
  for (const FitCase& c : cases) {
    const ReplayTrack track = replay(c.setup, module, c.log);
    for (std::size_t k = 0; k < c.log.rows.size(); ++k) {
      *out++ = track.position_deg[k] - logged_position_deg(c.log.rows[k].pd_in);
    }
  }
}

std::size_t residual_count(const std::vector<FitCase>& cases) {
  std::size_t m = 0;
  for (const FitCase& c : cases) m += c.log.rows.size();
  return m;
}

// One residual block: every logged position. The Jacobian is taken by
// forward differences, one replay per constant, in parallel (A-CAL-3).
class ReplayCost final : public ceres::CostFunction {
 public:
  ReplayCost(const std::vector<FitCase>& cases, const ModelCard& start, const Unknowns& u, int threads, double step)
      : cases_(cases), start_(start), u_(u), threads_(threads), step_(step) {
    set_num_residuals(static_cast<int>(residual_count(cases)));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(u.card_index.size()));
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const std::size_t n = u_.card_index.size();
    const std::size_t m = static_cast<std::size_t>(num_residuals());
    const double* x = parameters[0];
    if (!jacobians || !jacobians[0]) {
      residuals_into(cases_, card_at(start_, u_, x), residuals);
      last_x_.assign(x, x + n); // Ceres asks for the Jacobian where a trial step succeeded
      last_residuals_.assign(residuals, residuals + m);
      return true;
    }
    // Column 0: the point itself; columns 1 + 2i and 2 + 2i: constant i
    // stepped up and down (central differences; one-sided at a bound).
    std::vector<std::vector<double>> columns(2 * n + 1, std::vector<double>(m));
    std::vector<double> up(n), down(n);
    for (std::size_t i = 0; i < n; ++i) {
      up[i] = std::min(x[i] + step_, u_.hi[i]);
      down[i] = std::max(x[i] - step_, u_.lo[i]);
    }
    // The point itself was replayed already when it was a trial step (the
    // replay is deterministic): 2n replays instead of 2n + 1 (issue 31).
    const bool known = last_x_.size() == n && std::equal(last_x_.begin(), last_x_.end(), x);
    if (known) columns[0] = last_residuals_;
    const std::size_t first = known ? 1 : 0;
    io::parallel_for(2 * n + 1 - first, threads_, [&](std::size_t k) {
      const std::size_t j = k + first;
      std::vector<double> xj(x, x + n);
      if (j > 0) xj[(j - 1) / 2] = (j % 2 == 1) ? up[(j - 1) / 2] : down[(j - 1) / 2];
      residuals_into(cases_, card_at(start_, u_, xj.data()), columns[j].data());
    });
    std::copy(columns[0].begin(), columns[0].end(), residuals);
    for (std::size_t r = 0; r < m; ++r) {
      for (std::size_t i = 0; i < n; ++i) {
        jacobians[0][r * n + i] = (columns[1 + 2 * i][r] - columns[2 + 2 * i][r]) / (up[i] - down[i]);
      }
    }
    return true;
  }

 private:
  const std::vector<FitCase>& cases_;
  const ModelCard& start_;
  const Unknowns& u_;
  int threads_;
  double step_;
  // The last point replayed without a Jacobian and its residuals (Ceres
  // evaluates on one thread: options.num_threads = 1).
  mutable std::vector<double> last_x_, last_residuals_;
};

// Reports every solver iteration to FitOptions::progress, counting across
// the restarts (iteration 0 of a solve is its start, not an iteration).
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

double rms(const std::vector<double>& r) {
  double sum = 0;
  for (double v : r) sum += v * v;
  return r.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(r.size()));
}

// Integrated autocorrelation time of the residuals, pooled over the cases:
// tau = 1 + 2 sum_k rho_k, summed until rho_k first drops below 0.05 (Sokal's
// window). A replay's error is smooth in time and the encoder's
// quantisation repeats while the axis stands, so neighbouring rows are not
// independent samples: the variance is widened by tau (A-CAL-4).
double autocorrelation_time(const std::vector<FitCase>& cases, const std::vector<double>& r) {
  constexpr std::size_t kMaxLag = 2000;
  constexpr double kCutoff = 0.05;
  double den = 0;
  for (double v : r) den += v * v;
  if (den <= 0) return 1.0;
  double tau = 1.0;
  for (std::size_t lag = 1; lag < kMaxLag; ++lag) {
    double num = 0;
    std::size_t offset = 0;
    for (const FitCase& c : cases) {
      const std::size_t rows = c.log.rows.size();
      for (std::size_t k = 0; k + lag < rows; ++k) num += r[offset + k] * r[offset + k + lag];
      offset += rows;
    }
    const double rho = num / den;
    if (rho < kCutoff) break;
    tau += 2 * rho;
  }
  return tau;
}

} // namespace

std::vector<std::string> default_fit_names() {
  return {"coulomb_friction", "viscous_friction", "stribeck_excess", "torsional_stiffness", "torsional_damping"};
}

std::vector<double> position_residuals_deg(const std::vector<FitCase>& cases, const ModelCard& card) {
  std::vector<double> r(residual_count(cases));
  residuals_into(cases, card, r.data());
  return r;
}

FitResult fit_model(const std::vector<FitCase>& cases, const ModelCard& start, const FitOptions& options) {
  const std::vector<std::string> names = options.names.empty() ? default_fit_names() : options.names;
  const Unknowns u = unknowns_of(start, names);
  const std::size_t n = names.size();
  std::vector<double> x(n, 1.0);
  for (std::size_t i = 0; i < n; ++i) x[i] = std::clamp(start.constants[u.card_index[i]].value / u.scale[i], u.lo[i], u.hi[i]);

  FitResult result;
  result.residuals = residual_count(cases);
  result.start_rms_residual_deg = rms(position_residuals_deg(cases, start));

  auto* cost = new ReplayCost(cases, start, u, options.threads, options.relative_step);
  ceres::Problem problem; // owns cost
  problem.AddResidualBlock(cost, nullptr, x.data());
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
  int iterations = 0;
  IterationProgress progress(options, iterations);
  if (options.progress) so.callbacks.push_back(&progress);
  ceres::Solver::Summary summary;
  for (int solve = 0; solve < kMaxSolves; ++solve) {
    ceres::Solve(so, &problem, &summary);
    iterations += static_cast<int>(summary.iterations.size()) - 1;
    if (summary.termination_type != ceres::CONVERGENCE || !(summary.final_cost < (1 - kRestartGain) * summary.initial_cost)) break;
  }

  // The Jacobian and residuals at the solution, for the intervals.
  const std::size_t m = result.residuals;
  std::vector<double> r(m), jac(m * n);
  const double* params[] = {x.data()};
  double* jacs[] = {jac.data()};
  cost->Evaluate(params, r.data(), jacs);
  result.rms_residual_deg = rms(r);
  result.iterations = iterations;
  result.solver_message = summary.message;
  result.converged = summary.termination_type == ceres::CONVERGENCE &&
                     result.rms_residual_deg <= options.max_rms_residual_deg;
  result.card = card_at(start, u, x.data());

  Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> J(
      jac.data(), static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(n));
  const Eigen::MatrixXd JtJ = J.transpose() * J;
  result.autocorrelation_rows = autocorrelation_time(cases, r);
  const double dof = std::max<double>(1.0, static_cast<double>(m) - static_cast<double>(n));
  const double sigma2 = static_cast<double>(m) * result.rms_residual_deg * result.rms_residual_deg / dof *
                        result.autocorrelation_rows;
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(JtJ);
  const Eigen::MatrixXd cov = cod.pseudoInverse() * sigma2;
  const bool singular = cod.rank() < static_cast<Eigen::Index>(n);
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
