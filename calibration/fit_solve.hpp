// One solve of the fit (calibration/fit.cpp): Ceres' bounded trust region
// on the replay cost from a point, restarted while that pays (A-CAL-3,
// A-CAL-8), with the solver options the fit's speed and honesty rest on.
// Internal to calibration/.
#pragma once
#include <memory>
#include <mutex>
#include <vector>

#include <ceres/ceres.h>

#include "calibration/fit_cost.hpp"

namespace sreh {

inline constexpr int kMaxSolves = 4;         // restarts of the trust region
inline constexpr double kRestartGain = 0.01; // a restart must lower the cost by 1 %

// Reports every solver iteration to FitOptions::progress, counting across
// the starts, restarts and stages (iteration 0 of a solve is its start, not
// an iteration). The starts run concurrently: one count, one caller at a time.
class IterationProgress final : public ceres::IterationCallback {
 public:
  explicit IterationProgress(const FitOptions& options) : options_(options) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (s.iteration > 0) {
      const std::lock_guard lock(mutex_);
      options_.progress(++done_, options_.max_iterations);
    }
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const FitOptions& options_;
  std::mutex mutex_;
  int done_ = 0;
};

struct Stage {
  std::unique_ptr<ReplayCost> cost;
  ceres::Solver::Summary summary;
  bool converged = false; // Ceres' own tolerances (function, gradient, parameter)
};

struct SolveLimits {
  int max_iterations = 25;
  int max_solves = kMaxSolves; // 1: no restart (a spread start's few iterations)
  int threads = 2;             // replays in parallel
};

// Solves `cases` from x (updated in place), restarted while that pays
// (A-CAL-3); `iterations` counts on across stages.
Stage solve(const std::vector<FitCase>& cases, const ModelCard& start, const Unknowns& u, std::vector<double>& x,
            const FitOptions& options, const SolveLimits& limits, int& iterations, IterationProgress* progress);

} // namespace sreh
