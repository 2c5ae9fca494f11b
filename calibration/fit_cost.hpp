// The fit's pieces under Ceres (calibration/fit.cpp): the unknowns (card
// constants scaled by their start values), the residual block that replays
// the logs, and the statistics of a solution (rms, autocorrelation,
// covariance). Internal to calibration/.
#pragma once
#include <cstddef>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <ceres/ceres.h>

#include "calibration/fit.hpp"

namespace sreh {

// Card constants and, with --fit load, the attached load (A-CAL-14): one
// factor per stated load, shared by the logs that state it.
inline constexpr std::size_t kLoadUnknown = static_cast<std::size_t>(-1);
struct Unknowns {
  std::vector<std::size_t> card_index; // into ModelCard::constants; kLoadUnknown for a load factor
  std::vector<double> scale;           // value = u * scale (the start value; a load: the stated g cm^2, u its factor)
  std::vector<double> lo, hi;          // bounds on u
  bool temperature = false;            // a thermal constant is fitted: the polled temperatures are residuals too
  std::vector<std::string> load_name;  // per unknown: the load's name ("" for a card constant)
  std::vector<std::ptrdiff_t> case_load; // per case: the unknown scaling its load, -1 none
  bool is_load(std::size_t i) const { return card_index[i] == kLoadUnknown; }
};

// Where the fit stands: the card with the constants, and each case's load
// factor (1: the stated load).
struct FitPoint {
  ModelCard card;
  std::vector<double> load_scale; // per case; empty: all 1
};

// A polled temperature's residual in position degrees: each measurement
// weighed by its resolution, one wire count (360/2^16 deg, manual 2.5)
// against one step of index 112 (0.5 degC, manual 6.4) (A-CAL-9).
inline constexpr double kTemperatureWeight_deg_per_C = (360.0 / 65536.0) / 0.5;

// Throws CalibrationInputError for a name not on the card (nor the load),
// named twice, or whose range is a single value; for the load, when no
// case states one to scale or the stated load cannot be scaled.
Unknowns unknowns_of(const ModelCard& start, const std::vector<std::string>& names, const std::vector<FitCase>& cases);
ModelCard card_at(const ModelCard& start, const Unknowns& u, const double* x);
FitPoint point_at(const ModelCard& start, const Unknowns& u, const double* x, std::size_t case_count);
std::size_t position_count(const std::vector<FitCase>& cases);    // logged rows
std::size_t temperature_count(const std::vector<FitCase>& cases); // rows with a polled temperature
std::size_t residual_count(const std::vector<FitCase>& cases, const Unknowns& u);
// Replays every case with `card`: simulated - logged position (deg) for
// every row in case order, then, with `temperature`, simulated - polled
// temperature times kTemperatureWeight_deg_per_C for every polled row.
// Each case's load scaled by `point`'s factor for it.
void residuals_into(const std::vector<FitCase>& cases, const FitPoint& point, double* out, bool temperature);

// One residual block: every logged position. The Jacobian is taken by
// central differences, two replays per constant, in parallel (A-CAL-3).
// A replay is deterministic, so a point replayed before is not replayed
// again: Ceres evaluates a trial step's cost, then asks for the Jacobian
// there when it accepts it, and a restarted solve, the stopping test and
// the intervals ask for the Jacobian where the last one was taken (A-CAL-8).
class ReplayCost final : public ceres::CostFunction {
 public:
  // `cases`, `start` and `u` must outlive the cost.
  ReplayCost(const std::vector<FitCase>& cases, const ModelCard& start, const Unknowns& u, int threads, double step);
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

  // The last Jacobian (row-major, residuals x unknowns) and the residuals it
  // was taken with, if it was taken at `x`; else nullptrs.
  const std::vector<double>* jacobian_at(const double* x) const;
  const std::vector<double>& jacobian_residuals() const { return jacobian_residuals_; }
  std::size_t replays() const { return replays_; } // whole replays of every case so far

 private:
  static constexpr std::size_t kKnownPoints = 4; // a trial step and its line search's points
  const std::vector<double>* known_residuals(const std::vector<double>& x) const;
  void remember(const std::vector<double>& x, std::vector<double> r) const;

  const std::vector<FitCase>& cases_;
  const ModelCard& start_;
  const Unknowns& u_;
  int threads_;
  double step_;
  // Ceres evaluates on one thread (options.num_threads = 1): plain members.
  mutable std::vector<std::pair<std::vector<double>, std::vector<double>>> known_; // points replayed, oldest first
  mutable std::vector<double> jacobian_x_, jacobian_residuals_, jacobian_;
  mutable std::size_t replays_ = 0;
};

double rms(const std::vector<double>& r);

// Integrated autocorrelation time of the residuals, pooled over the cases (A-CAL-4).
double autocorrelation_time(const std::vector<FitCase>& cases, const std::vector<double>& r);

// The unknowns' covariance from the Jacobian at a solution (A-CAL-4):
// (J^T J)^+ times the residual variance, widened by the autocorrelation time.
struct Covariance {
  Eigen::MatrixXd cov;          // of the scaled unknowns
  Eigen::VectorXd gauss_newton; // the step -(J^T J)^+ J^T r the linear model still predicts
  bool singular = false;
  double rms = 0;
  double autocorrelation_rows = 1;
};
Covariance covariance_at(const std::vector<FitCase>& cases, const std::vector<double>& residuals,
                         const std::vector<double>& jacobian, std::size_t unknowns);

} // namespace sreh
