#include "calibration/fit_solve.hpp"

namespace sreh {

Stage solve(const std::vector<FitCase>& cases, const ModelCard& start, const Unknowns& u, std::vector<double>& x,
            const FitOptions& options, const SolveLimits& limits, int& iterations, IterationProgress* progress) {
  const std::size_t n = x.size();
  Stage stage;
  stage.cost = std::make_unique<ReplayCost>(cases, start, u, limits.threads, options.relative_step);
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
  so.max_num_iterations = limits.max_iterations;
  so.logging_type = ceres::SILENT;
  so.minimizer_progress_to_stdout = false;
  // Ceres' own tests end a solve (A-CAL-8, issue 36): a step that changes
  // the cost by less than 1e-4 of it, or the scaled constants by less than
  // 1e-4 (0.01 % of a start value, far inside any interval). Monotonic
  // steps: on the count-rough cost a non-monotonic trust region wanders
  // without end at the floor; a failed step shrinks it until the parameter
  // test ends the solve, and the spread starts (not a wider step) guard
  // against a dip it ends in. A fresh solve from the result restores a
  // trust region that shrank on the roughness, as long as that still
  // lowers the cost by 1 % (A-CAL-3).
  so.function_tolerance = 1e-4;
  so.parameter_tolerance = 1e-4;
  so.num_threads = 1; // the replays are parallel already
  so.use_nonmonotonic_steps = false;
  // With bounds Ceres refines each trust-region step by a line search; its
  // default cubic interpolation asks for the gradient, a whole Jacobian of
  // 2n replays, at every trial step size. Quadratic interpolation needs the
  // cost only, one replay per trial (A-CAL-8).
  so.line_search_interpolation_type = ceres::QUADRATIC;
  // One trial per step: on the count-rough cost a trust-region step that
  // fails rarely succeeds shortened along the same direction, and each of
  // the line search's backtracks is a replay (3-4 per failed step on the
  // 60 s log, 27 of its 46 s of whole-log stage; A-CAL-8). A failed step
  // shrinks the trust region instead, which turns the next step too.
  so.max_num_line_search_step_size_iterations = 1;
  if (progress) so.callbacks.push_back(progress);
  for (int attempt = 0; attempt < limits.max_solves; ++attempt) {
    ceres::Solve(so, &problem, &stage.summary);
    iterations += static_cast<int>(stage.summary.iterations.size()) - 1;
    if (stage.summary.termination_type != ceres::CONVERGENCE ||
        !(stage.summary.final_cost < (1 - kRestartGain) * stage.summary.initial_cost)) {
      break;
    }
  }
  stage.converged = stage.summary.termination_type == ceres::CONVERGENCE;
  return stage;
}

} // namespace sreh
