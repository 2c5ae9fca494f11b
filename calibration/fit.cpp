#include "calibration/fit.hpp"

#include <algorithm>
#include <cmath>
#include <future>

#include <fmt/format.h>

#include "calibration/fit_adequacy.hpp"
#include "calibration/fit_cost.hpp"
#include "calibration/fit_refit.hpp"
#include "calibration/fit_solve.hpp"
#include "calibration/load_scale.hpp"
#include "io/parallel.hpp"
#include "twin/load_builder.hpp"

namespace sreh {
namespace {

constexpr double kZ95 = 1.959963984540054;     // two-sided 95 % of the normal distribution
constexpr double kAtBound = 0.001;             // within 0.1 % of the range from a bound: at it
constexpr int kLikelihoodProbes = 5;           // step-outs per side, each twice the last
constexpr unsigned kRefitSeed = 36;            // the bootstrap's noise, refit b's seed kRefitSeed + b (A-CAL-12)
// Logs longer than twice this are first fitted on their first kCoarse_s
// (shared out in proportion to their lengths; the plan is ~9 s), then on
// the whole from there (A-CAL-8).
constexpr double kCoarse_s = 10.0;

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

std::vector<double> position_residuals_deg(const std::vector<FitCase>& cases, const ModelCard& card,
                                           const std::vector<double>& load_scale) {
  std::vector<double> r(position_count(cases));
  residuals_into(cases, FitPoint{card, load_scale}, r.data(), false);
  return r;
}

std::vector<FitCase> with_fitted_load(std::vector<FitCase> cases, const std::vector<double>& load_scale) {
  for (std::size_t k = 0; k < cases.size() && k < load_scale.size(); ++k) cases[k].setup.load_scale *= load_scale[k];
  return cases;
}

namespace {

// The chi-square distribution's 95 % quantile with k degrees of freedom:
// a table to 10, Wilson-Hilferty above.
double chi2_95(std::size_t k) {
  static constexpr double kTable[] = {3.841, 5.991, 7.815, 9.488, 11.070, 12.592, 14.067, 15.507, 16.919, 18.307};
  if (k >= 1 && k <= 10) return kTable[k - 1];
  const double d = static_cast<double>(k);
  const double a = 2.0 / (9.0 * d);
  return d * std::pow(1 - a + 1.6449 * std::sqrt(a), 3);
}

double sum_of_squares(const std::vector<double>& r, std::size_t count) {
  double s = 0;
  for (std::size_t k = 0; k < count; ++k) s += r[k] * r[k];
  return s;
}

// The starts of a fit (issue 36): the start card, then points spread over
// the ranges by an additive recurrence (Roberts' R-sequence: each constant
// stepped by its own irrational fraction of its range), deterministic.
std::vector<std::vector<double>> start_points(const Unknowns& u, const std::vector<double>& card_x, int count) {
  std::vector<std::vector<double>> starts{card_x};
  const std::size_t n = card_x.size();
  double phi = 2; // the plastic-number generalisation: phi^(n+1) = phi + 1
  for (int k = 0; k < 30; ++k) phi = std::pow(1 + phi, 1.0 / static_cast<double>(n + 1));
  for (int k = 1; k < count; ++k) {
    std::vector<double> x(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double f = std::fmod(0.5 + static_cast<double>(k) / std::pow(phi, static_cast<double>(i + 1)), 1.0);
      // Keep clear of the bounds by a tenth of the range: a start at a bound
      // tells nothing about whether the minimum is there.
      x[i] = u.lo[i] + (0.1 + 0.8 * f) * (u.hi[i] - u.lo[i]);
    }
    starts.push_back(std::move(x));
  }
  return starts;
}

// Refit b of the bootstrap (A-CAL-12): a log the fitted card records at
// 1 / (kFirstStepDivisor + b) of the physics step, with draw b of the log's
// noise, fitted again from `from` (one start solved to convergence, no
// probes, no bootstrap of its own); apply_bootstrap
// (calibration/fit_refit.hpp) turns the refits into intervals. A long log's
// refit is of its first seconds (A-CAL-8): cheaper, and a shorter log's
// error is the larger, so the interval is on the safe side.
FitResult refit_of(const std::vector<FitCase>& cases, const ModelCard& from, const FitOptions& options,
                   const std::vector<std::string>& names, const FitPoint& fitted, double noise_counts, int b) {
  FitOptions o = options;
  o.names = names;
  o.starts = 1;
  o.bootstrap = 0;
  o.likelihood_probes = false;
  o.progress = nullptr;
  o.noise_counts = noise_counts;
  const std::vector<FitCase> coarse = coarse_cases(cases);
  const unsigned seed = kRefitSeed + static_cast<unsigned>(b);
  FitResult refit = fit_model(synthetic_cases(coarse.empty() ? cases : coarse, fitted.card, fitted.load_scale, noise_counts,
                                              seed, kFirstStepDivisor + b),
                              from, o);
  refit.replays += cases.size(); // the synthetic logs' recordings
  return refit;
}

// Unknown i as the fit reports it: a card constant (value and start from
// the cards, its range the card's) or a load (g cm^2: the stated load times
// the factor, started at the stated load, A-CAL-14).
FittedConstant fitted_entry(const ModelCard& start, const ModelCard& fitted, const Unknowns& u, const std::vector<double>& x,
                            std::size_t i) {
  FittedConstant f;
  if (u.is_load(i)) {
    f.name = u.load_name[i];
    f.unit = "g cm^2";
    f.load = true;
    f.value = x[i] * u.scale[i];
    f.start = u.scale[i];
    f.range_lo = u.lo[i] * u.scale[i];
    f.range_hi = u.hi[i] * u.scale[i];
    return f;
  }
  const ModelConstant& c = fitted.constants[u.card_index[i]];
  f.name = c.name;
  f.unit = c.unit;
  f.value = c.value;
  f.start = start.constants[u.card_index[i]].value;
  f.range_lo = c.range_lo;
  f.range_hi = c.range_hi;
  return f;
}

std::string unknown_name(const ModelCard& start, const Unknowns& u, std::size_t i) {
  return u.is_load(i) ? u.load_name[i] : start.constants[u.card_index[i]].name;
}

constexpr const char* kLoadAtBound =
    "the module carries a load 30 % or more away from the stated one (or the heaviest it may carry), or the model is "
    "wrong";

// The fitted load against the stated one, in words (A-CAL-14).
std::string load_verdict(const FittedConstant& f) {
  const double change_pct = 100 * (f.value / f.start - 1);
  if (!f.identified) {
    return fmt::format("the load is not identified ({}): the module carries {} to {} g cm^2 (stated {})", f.note,
                       round_gcm2(f.ci95_lo), round_gcm2(f.ci95_hi), round_gcm2(f.start));
  }
  if (f.ci95_lo > f.start || f.ci95_hi < f.start) {
    return fmt::format("the module carries {} g cm^2, not the stated {} ({:+.1f} %; 95 % interval {} to {} g cm^2)",
                       round_gcm2(f.value), round_gcm2(f.start), change_pct, round_gcm2(f.ci95_lo), round_gcm2(f.ci95_hi));
  }
  return fmt::format("the module carries the stated load: {} g cm^2 is inside the fitted load's 95 % interval {} to {} "
                     "g cm^2 (fitted {}, {:+.1f} %)",
                     round_gcm2(f.start), round_gcm2(f.ci95_lo), round_gcm2(f.ci95_hi), round_gcm2(f.value), change_pct);
}

struct StartOutcome {
  std::vector<double> x;
  double sum_squares = 0; // of the position residuals, on the cases it was solved on
  int iterations = 0;
};

} // namespace

FitResult fit_model(const std::vector<FitCase>& cases, const ModelCard& start, const FitOptions& options) {
  // The load alone is named: the module's default constants join it (the
  // load is a question about the setup, asked along with the module's).
  const bool load_only = !options.names.empty() && std::all_of(options.names.begin(), options.names.end(), is_load_name);
  const DefaultFit by_default = options.names.empty() || load_only ? default_fit(cases, start) : DefaultFit{};
  std::vector<std::string> names = options.names.empty() || load_only ? by_default.names : options.names;
  if (load_only) names.insert(names.end(), options.names.begin(), options.names.end());
  const Unknowns u = unknowns_of(start, names, cases);
  const std::size_t n = u.card_index.size(); // a load named once is one unknown per stated load
  std::vector<double> card_x(n, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (!u.is_load(i)) card_x[i] = std::clamp(start.constants[u.card_index[i]].value / u.scale[i], u.lo[i], u.hi[i]);
  }

  FitResult result;
  result.residuals = position_count(cases);
  result.temperature_residuals = u.temperature ? temperature_count(cases) : 0;
  const std::vector<double> start_residuals = position_residuals_deg(cases, start);
  result.start_rms_residual_deg = rms(start_residuals);
  result.replays = 1;
  if (!by_default.note.empty()) result.notes.push_back(by_default.note);

  // Several starts (issue 36, A-CAL-8): the start card solved to Ceres'
  // own convergence, spread points with a few iterations each; the best
  // goes on. A long log is first solved on its first seconds.
  const std::vector<FitCase> coarse = coarse_cases(cases);
  const std::vector<FitCase>& first_cases = coarse.empty() ? cases : coarse;
  const std::size_t first_positions = position_count(first_cases);
  // The starts are independent: they run concurrently, and the best is
  // chosen by cost alone (ties to the earlier start), so the result does
  // not depend on the scheduling. Each may use every thread for its
  // Jacobians: the spread starts end early, and the card's start, solved
  // on, would otherwise leave the other cores idle (a third of a 60 s log's
  // wall time).
  IterationProgress progress(options);
  IterationProgress* reports = options.progress ? &progress : nullptr;
  const std::vector<std::vector<double>> points = start_points(u, card_x, options.starts);
  const int concurrent = std::min(std::max(1, options.threads), static_cast<int>(points.size()));
  std::vector<StartOutcome> outcomes(points.size());
  std::vector<Stage> stages(points.size());
  io::parallel_for(points.size(), concurrent, [&](std::size_t k) {
    StartOutcome& o = outcomes[k];
    o.x = points[k];
    SolveLimits limits;
    limits.threads = std::max(1, options.threads);
    if (k > 0) { // a spread start: a few iterations, no restart
      limits.max_iterations = options.spread_start_iterations;
      limits.max_solves = 1;
    } else {
      limits.max_iterations = options.max_iterations;
    }
    stages[k] = solve(first_cases, start, u, o.x, options, limits, o.iterations, reports);
    std::vector<double> r(residual_count(first_cases, u));
    const double* params[] = {o.x.data()};
    stages[k].cost->Evaluate(params, r.data(), nullptr); // remembered: no replay
    o.sum_squares = sum_of_squares(r, first_positions);
  });
  int iterations = 0;
  std::size_t best = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    iterations += outcomes[k].iterations;
    result.replays += stages[k].cost->replays();
    if (outcomes[k].sum_squares < outcomes[best].sum_squares) best = k;
  }
  Stage best_stage = std::move(stages[best]);
  stages.clear();
  // The best first, the others after it in start order.
  std::rotate(outcomes.begin(), outcomes.begin() + static_cast<std::ptrdiff_t>(best),
              outcomes.begin() + static_cast<std::ptrdiff_t>(best) + 1);
  std::vector<double> x = outcomes.front().x;
  SolveLimits full;
  full.max_iterations = options.max_iterations;
  full.threads = std::max(1, options.threads);
  if (!best_stage.converged) { // a spread start that was best after its few iterations, or the limit: on to convergence
    best_stage = solve(first_cases, start, u, x, options, full, iterations, reports);
    result.replays += best_stage.cost->replays();
    std::vector<double> r(residual_count(first_cases, u));
    const double* params[] = {x.data()};
    best_stage.cost->Evaluate(params, r.data(), nullptr);
    outcomes.front().x = x;
    outcomes.front().sum_squares = sum_of_squares(r, first_positions);
  }
  // The bootstrap's refits (A-CAL-12) need the fitted card only. On a long
  // log the whole-log stage rarely moves the first stage's answer (its
  // steps on the count-rough cost fail one replay at a time, one core
  // busy): the refits start now from that answer, and are kept only if the
  // whole-log stage ends exactly there; otherwise they are run again from
  // where it ended. The result is the same either way.
  result.noise_counts = options.noise_counts ? *options.noise_counts : estimated_noise_counts(cases);
  const std::size_t refit_count = static_cast<std::size_t>(std::max(0, options.bootstrap));
  const std::vector<std::vector<double>> refit_starts = start_points(u, card_x, static_cast<int>(refit_count));
  auto refits_of = [&](const FitPoint& fitted) {
    std::vector<FitResult> out(refit_count);
    io::parallel_for(refit_count, options.threads, [&](std::size_t b) {
      out[b] = refit_of(cases, card_at(start, u, refit_starts[b].data()), options, names, fitted, result.noise_counts,
                        static_cast<int>(b));
    });
    return out;
  };
  const std::vector<double> first_stage_x = x;
  std::future<std::vector<FitResult>> early_refits;
  if (!coarse.empty() && refit_count > 0) {
    early_refits = std::async(std::launch::async, refits_of, point_at(start, u, x.data(), cases.size()));
  }
  Stage stage = coarse.empty() ? std::move(best_stage) : solve(cases, start, u, x, options, full, iterations, reports);
  if (!coarse.empty()) result.replays += stage.cost->replays();

  // The Jacobian and residuals at the solution, for the intervals.
  const std::size_t positions = result.residuals;
  const std::size_t m = positions + result.temperature_residuals;
  std::vector<double> r(m), jac(m * n);
  {
    const double* params[] = {x.data()};
    double* jacs[] = {jac.data()};
    const std::size_t before = stage.cost->replays();
    stage.cost->Evaluate(params, r.data(), jacs);
    result.replays += stage.cost->replays() - before;
  }
  const Covariance cv = covariance_at(cases, r, jac, n);
  const auto split = r.begin() + static_cast<std::ptrdiff_t>(positions);
  const std::vector<double> position_r(r.begin(), split);
  result.rms_residual_deg = rms(position_r);
  result.rms_temperature_residual_C = rms(std::vector<double>(split, r.end())) / kTemperatureWeight_deg_per_C;
  result.autocorrelation_rows = cv.autocorrelation_rows;
  result.iterations = iterations;
  result.solver_message = stage.summary.message;
  result.starts = static_cast<int>(outcomes.size());
  const FitPoint fitted = point_at(start, u, x.data(), cases.size());
  result.card = fitted.card;
  if (std::any_of(u.case_load.begin(), u.case_load.end(), [](std::ptrdiff_t i) { return i >= 0; })) {
    result.load_scale = fitted.load_scale;
  }

  // A likelihood-ratio region (A-CAL-4): points whose sum of squares is
  // within chi2_95 effective residual variances of the best are as
  // consistent with the log as the best. sigma2_eff = rms^2 tau per row.
  const double sigma2_eff = result.rms_residual_deg * result.rms_residual_deg * cv.autocorrelation_rows;
  const double best_ss = sum_of_squares(position_r, positions);
  const double start_ss = sum_of_squares(start_residuals, positions);
  const double joint_threshold = chi2_95(n) * sigma2_eff;
  const double single_threshold = chi2_95(1) * sigma2_eff;

  const Eigen::MatrixXd& cov = cv.cov;
  result.correlation.assign(n, std::vector<double>(n, 0.0));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      const auto ii = static_cast<Eigen::Index>(i), jj = static_cast<Eigen::Index>(j);
      const double d = std::sqrt(cov(ii, ii) * cov(jj, jj));
      result.correlation[i][j] = d > 0 ? cov(ii, jj) / d : 0.0;
    }
  }
  // The intervals (likelihood probes) and the bootstrap's refits do not
  // depend on each other: they run concurrently, and the bootstrap widens
  // the intervals after all of them. Refit b starts from the start card
  // (b = 0) or the b-th spread point of the ranges (the points the fit's
  // own starts use), one start each: where the data leave a constant flat
  // and the fit ended near its start, the refits from elsewhere end
  // elsewhere and show it (the fit's own three starts from every refit
  // would all keep the card's, which on a flat constant is a refit started
  // at its own answer: CalibrationCases.TruthRecordedAtAFinerPhysicsStep,
  // damping).
  std::future<std::vector<FitResult>> refits_running;
  if (early_refits.valid() && x == first_stage_x) {
    refits_running = std::move(early_refits);
  } else if (refit_count > 0) {
    refits_running = std::async(std::launch::async, refits_of, fitted);
  }
  {
    // The curvature's interval assumes a smooth cost; on the replay's rough
    // one, step out from the solution along the linearised profile path
    // (constant i moved, the others as the covariance says they follow:
    // x + t C[:, i] / C[i, i]) while the sum of squares stays within the
    // single-constant threshold: a profile likelihood interval at one
    // replay per probe, without a sub-fit per point. Each constant's two
    // sides are a chain of probes of their own: the 2n chains run
    // concurrently (beside the refits; a 60 s log's probes are 60 s
    // replays), each writing only its own slot.
    std::vector<double> reached(2 * n);
    std::vector<std::size_t> probe_replays(2 * n, 0);
    io::parallel_for(2 * n, options.likelihood_probes ? options.threads : 1, [&](std::size_t chain) {
      const std::size_t i = chain / 2;
      const int side = chain % 2 == 0 ? -1 : +1;
      const auto ii = static_cast<Eigen::Index>(i);
      const double half_u = kZ95 * std::sqrt(std::max(0.0, cov(ii, ii)));
      Eigen::VectorXd path = cov.col(ii);
      if (cov(ii, ii) > 0) path /= cov(ii, ii);
      else path = Eigen::VectorXd::Unit(static_cast<Eigen::Index>(n), ii);
      double step = std::max(half_u, 0.01 * (u.hi[i] - u.lo[i]));
      double reach = side < 0 ? std::max(u.lo[i], x[i] - half_u) : std::min(u.hi[i], x[i] + half_u);
      for (int probe = 0; probe < (options.likelihood_probes ? kLikelihoodProbes : 0); ++probe) {
        std::vector<double> xp = x;
        for (std::size_t j = 0; j < n; ++j) {
          xp[j] = std::clamp(x[j] + side * step * path(static_cast<Eigen::Index>(j)), u.lo[j], u.hi[j]);
        }
        if (xp[i] == x[i]) break;
        std::vector<double> rp(positions);
        residuals_into(cases, point_at(start, u, xp.data(), cases.size()), rp.data(), false);
        ++probe_replays[chain];
        if (sum_of_squares(rp, positions) - best_ss > single_threshold) break;
        reach = side < 0 ? std::min(reach, xp[i]) : std::max(reach, xp[i]);
        if (xp[i] == (side < 0 ? u.lo[i] : u.hi[i])) break;
        step *= 2;
      }
      reached[chain] = reach;
    });
    for (const std::size_t count : probe_replays) result.replays += count;
    for (std::size_t i = 0; i < n; ++i) {
      FittedConstant f = fitted_entry(start, result.card, u, x, i);
      const auto ii = static_cast<Eigen::Index>(i);
      const double half_u = kZ95 * std::sqrt(std::max(0.0, cov(ii, ii)));
      double lo_u = reached[2 * i], hi_u = reached[2 * i + 1];
      f.likelihood_widened = lo_u < x[i] - half_u * (1 + 1e-9) || hi_u > x[i] + half_u * (1 + 1e-9);
      // Every other start that ended inside the joint region is an equally
      // good answer: the interval covers it, and if it lies outside the
      // curvature's interval the starts disagree.
      for (std::size_t k = 1; k < outcomes.size(); ++k) {
        const double excess = outcomes[k].sum_squares - outcomes.front().sum_squares;
        const double threshold = joint_threshold * static_cast<double>(first_positions) / static_cast<double>(positions);
        if (excess > threshold) continue;
        const double v = outcomes[k].x[i];
        if (v < x[i] - half_u || v > x[i] + half_u) f.starts_disagree = true;
        lo_u = std::min(lo_u, v);
        hi_u = std::max(hi_u, v);
      }
      // So is the start card itself when its sum of squares is inside the
      // joint region: the data do not tell the fit from where it began.
      bool start_as_good = false;
      if (start_ss - best_ss <= joint_threshold) {
        start_as_good = card_x[i] < x[i] - half_u || card_x[i] > x[i] + half_u;
        lo_u = std::min(lo_u, card_x[i]);
        hi_u = std::max(hi_u, card_x[i]);
      }
      f.ci95_lo = f.likelihood_lo = lo_u * u.scale[i];
      f.ci95_hi = f.likelihood_hi = hi_u * u.scale[i];
      const double half = 0.5 * (f.ci95_hi - f.ci95_lo);
      const double range = f.range_hi - f.range_lo;
      f.at_bound = f.value <= f.range_lo + kAtBound * range || f.value >= f.range_hi - kAtBound * range;
      // Why a constant is not identified, the first reason that applies.
      if (cv.singular || half_u == 0) {
        f.note = "the data do not move the position: no interval";
      } else if (result.iterations == 0 || f.value == f.start) {
        f.note = "the solve did not move it from the start";
      } else if (f.at_bound) {
        f.note = f.load ? fmt::format("at its bound: {}", kLoadAtBound)
                        : "at its bound: the module lies outside the card's range, or the model is wrong";
      } else if (start_as_good) {
        f.note = "the start card explains the log as well: the data do not tell the fitted value from the start";
      } else if (f.starts_disagree) {
        f.note = "another start ends as well elsewhere: the interval covers both";
      } else if (half > kWideHalfWidth * std::abs(f.value)) {
        f.note = fmt::format("wide interval: +-{:.0f} % of the value", 100 * half / std::abs(f.value));
      }
      for (std::size_t j = 0; j < n && f.note.empty(); ++j) {
        if (j != i && std::abs(result.correlation[i][j]) > kStrongCorrelation) {
          f.note = fmt::format("correlated with {} (r = {:.2f})", unknown_name(start, u, j), result.correlation[i][j]);
        }
      }
      f.identified = f.note.empty();
      result.constants.push_back(f);
    }
  }
  const std::vector<FitResult> refits = refits_running.valid() ? refits_running.get() : std::vector<FitResult>{};
  if (early_refits.valid()) early_refits.wait(); // started from a point the whole-log stage left: not used
  apply_bootstrap(refits, result);
  for (const FitResult& refit : refits) result.replays += refit.replays;
  // A log the model does not explain (A-CAL-10) identifies nothing: the
  // intervals assume the model's form is right.
  result.floor_rms_deg = residual_floor_deg(result.noise_counts);
  result.adequate = result.rms_residual_deg <= kInadequateRatio * result.floor_rms_deg;
  for (FittedConstant& f : result.constants) {
    if (result.adequate || !f.identified) continue;
    f.identified = false;
    f.note = "the model does not explain this log: no interval is honest";
  }
  // A constant not identified has no interval to trust (issue 36): it
  // reports the card's range, which holds any module of the type.
  for (FittedConstant& f : result.constants) {
    if (f.identified) continue;
    f.ci95_lo = std::min(f.range_lo, f.ci95_lo);
    f.ci95_hi = std::max(f.range_hi, f.ci95_hi);
  }
  if (!result.adequate) {
    const std::vector<LogSegment> segments = log_segments(cases, position_r);
    const auto worst = std::max_element(segments.begin(), segments.end(),
                                        [](const LogSegment& a, const LogSegment& b) { return a.rms_deg < b.rms_deg; });
    result.inadequacy = fmt::format(
        "the model does not explain this log: rms residual {:.5f} deg is {:.1f} times the log's floor {:.5f} deg "
        "(quantisation and {:.2f} counts of noise); the largest residuals are in {}{}t {:.3f}..{:.3f} s, the command to "
        "{:.2f} deg (rms {:.5f} deg, mean {:+.5f} deg)",
        result.rms_residual_deg, result.rms_residual_deg / result.floor_rms_deg, result.floor_rms_deg, result.noise_counts,
        cases.size() > 1 ? cases[worst->log].log.path : std::string(), cases.size() > 1 ? " " : "", worst->t0_s, worst->t1_s,
        worst->target_deg, worst->rms_deg, worst->mean_deg);
  }
  for (const FittedConstant& f : result.constants) {
    if (f.at_bound) {
      result.notes.push_back(f.load ? fmt::format("{} ends at its bound: {}", f.name, kLoadAtBound)
                                    : fmt::format("{} ends at its bound: the module lies outside the card's range, or the "
                                                  "model is wrong",
                                                  f.name));
    }
    if (f.load) result.notes.push_back(load_verdict(f));
  }
  result.converged = stage.converged && result.rms_residual_deg <= options.max_rms_residual_deg;
  return result;
}

} // namespace sreh
