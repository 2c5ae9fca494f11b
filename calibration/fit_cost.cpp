#include "calibration/fit_cost.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "calibration/load_scale.hpp"
#include "device_logic/units.hpp"
#include "io/parallel.hpp"
#include "twin/load_builder.hpp"

namespace sreh {

namespace {

// The thermal model's constants (twin/thermal.hpp, A-TWIN-THERMAL-1, -2):
// they move the polled temperature, not the position.
bool is_thermal(const std::string& name) {
  return name == "winding_heat_capacity" || name == "housing_heat_capacity" || name == "winding_to_housing_resistance" ||
         name == "housing_to_ambient_resistance" || name == "speed_loss";
}

std::size_t polled_count(const MasterLog& log) {
  return static_cast<std::size_t>(
      std::count_if(log.rows.begin(), log.rows.end(), [](const MasterLogRow& r) { return r.temperature_C.has_value(); }));
}

} // namespace

namespace {

// The load unknowns (A-CAL-14): one per distinct stated load, shared by the
// logs that state it (the command line states one load for every log).
void add_load_unknowns(Unknowns& u, const std::string& name, const std::vector<FitCase>& cases) {
  if (std::any_of(u.load_name.begin(), u.load_name.end(), [](const std::string& n) { return !n.empty(); })) {
    throw CalibrationInputError(fmt::format("--fit {}: the load named twice", name));
  }
  u.case_load.assign(cases.size(), -1);
  std::vector<std::size_t> first_case; // of each load unknown
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const TwinConfig& config = cases[k].setup.config;
    if (std::holds_alternative<NoLoad>(config.load)) continue;
    if (const std::string why = why_not_scalable(config.load); !why.empty()) {
      throw CalibrationInputError(fmt::format("--fit {}: {}", name, why));
    }
    const double stated_gcm2 = cases[k].setup.load_scale *
                               kgm2_to_gcm2(built_load_inertia_kgm2(config.load, config.hard_stops, config.physics_dt_s));
    if (!(stated_gcm2 > 0)) continue;
    for (std::size_t j = 0; j < first_case.size(); ++j) {
      const FitCase& other = cases[first_case[j]];
      if (other.setup.config.load == config.load && other.setup.load_scale == cases[k].setup.load_scale) {
        u.case_load[k] = static_cast<std::ptrdiff_t>(u.card_index.size() - first_case.size() + j);
      }
    }
    if (u.case_load[k] >= 0) continue;
    first_case.push_back(k);
    u.case_load[k] = static_cast<std::ptrdiff_t>(u.card_index.size());
    u.card_index.push_back(kLoadUnknown);
    u.scale.push_back(stated_gcm2); // x is the factor, x * scale the carried load in g cm^2
    u.lo.push_back(kLoadScaleLo);
    u.hi.push_back(std::max(kLoadScaleLo, std::min(kLoadScaleHi, max_load_gcm2() / stated_gcm2)));
    u.load_name.push_back("load_inertia");
  }
  if (first_case.empty()) {
    throw CalibrationInputError(fmt::format("--fit {}: no load is stated (0 g cm^2): nothing to scale; state the load "
                                            "the module carries with --load-gcm2 or --load",
                                            name));
  }
  if (first_case.size() > 1) { // named by the first log that states it
    for (std::size_t j = 0; j < first_case.size(); ++j) {
      const std::size_t i = u.card_index.size() - first_case.size() + j;
      u.load_name[i] = fmt::format("load_inertia ({})", cases[first_case[j]].log.path);
    }
  }
}

} // namespace

Unknowns unknowns_of(const ModelCard& start, const std::vector<std::string>& names, const std::vector<FitCase>& cases) {
  Unknowns u;
  u.case_load.assign(cases.size(), -1);
  for (const std::string& name : names) {
    if (is_load_name(name)) {
      add_load_unknowns(u, name, cases);
      continue;
    }
    if (is_thermal(name)) u.temperature = true;
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
    u.load_name.emplace_back();
  }
  return u;
}

ModelCard card_at(const ModelCard& start, const Unknowns& u, const double* x) {
  ModelCard card = start;
  for (std::size_t i = 0; i < u.card_index.size(); ++i) {
    if (u.is_load(i)) continue;
    auto& c = card.constants[u.card_index[i]];
    c.value = std::clamp(x[i] * u.scale[i], c.range_lo, c.range_hi);
  }
  return card;
}

FitPoint point_at(const ModelCard& start, const Unknowns& u, const double* x, std::size_t case_count) {
  FitPoint p{card_at(start, u, x), std::vector<double>(case_count, 1.0)};
  for (std::size_t k = 0; k < case_count && k < u.case_load.size(); ++k) {
    if (u.case_load[k] >= 0) {
      const auto i = static_cast<std::size_t>(u.case_load[k]);
      p.load_scale[k] = std::clamp(x[i], u.lo[i], u.hi[i]);
    }
  }
  return p;
}

void residuals_into(const std::vector<FitCase>& cases, const FitPoint& point, double* out, bool temperature) {
  const ModuleModel module = point.card.module_model();
  double* position = out;
  double* polled = out + position_count(cases);
  for (std::size_t n = 0; n < cases.size(); ++n) {
    const FitCase& c = cases[n];
    ReplaySetup setup = c.setup;
    if (n < point.load_scale.size()) setup.load_scale *= point.load_scale[n];
    const ReplayTrack track = replay(setup, module, c.log);
    for (std::size_t k = 0; k < c.log.rows.size(); ++k) {
      const MasterLogRow& row = c.log.rows[k];
      *position++ = track.position_deg[k] - logged_position_deg(row.pd_in);
      if (temperature && row.temperature_C) *polled++ = kTemperatureWeight_deg_per_C * (track.temperature_C[k] - *row.temperature_C);
    }
  }
}

std::size_t position_count(const std::vector<FitCase>& cases) {
  std::size_t m = 0;
  for (const FitCase& c : cases) m += c.log.rows.size();
  return m;
}

std::size_t temperature_count(const std::vector<FitCase>& cases) {
  std::size_t m = 0;
  for (const FitCase& c : cases) m += polled_count(c.log);
  return m;
}

std::size_t residual_count(const std::vector<FitCase>& cases, const Unknowns& u) {
  return position_count(cases) + (u.temperature ? temperature_count(cases) : 0);
}

ReplayCost::ReplayCost(const std::vector<FitCase>& cases, const ModelCard& start, const Unknowns& u, int threads,
                       double step)
    : cases_(cases), start_(start), u_(u), threads_(threads), step_(step) {
  set_num_residuals(static_cast<int>(residual_count(cases, u)));
  mutable_parameter_block_sizes()->push_back(static_cast<int>(u.card_index.size()));
}

bool ReplayCost::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
  const std::size_t n = u_.card_index.size();
  const std::size_t m = static_cast<std::size_t>(num_residuals());
  const std::vector<double> x(parameters[0], parameters[0] + n);
  if (!jacobians || !jacobians[0]) {
    if (const std::vector<double>* known = known_residuals(x)) {
      std::copy(known->begin(), known->end(), residuals);
      return true;
    }
    residuals_into(cases_, point_at(start_, u_, x.data(), cases_.size()), residuals, u_.temperature);
    ++replays_;
    remember(x, std::vector<double>(residuals, residuals + m));
    return true;
  }
  if (x == jacobian_x_) {
    std::copy(jacobian_residuals_.begin(), jacobian_residuals_.end(), residuals);
    std::copy(jacobian_.begin(), jacobian_.end(), jacobians[0]);
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
  const std::vector<double>* known = known_residuals(x);
  if (known) columns[0] = *known;
  const std::size_t first = known ? 1 : 0;
  io::parallel_for(2 * n + 1 - first, threads_, [&](std::size_t k) {
    const std::size_t j = k + first;
    std::vector<double> xj = x;
    if (j > 0) xj[(j - 1) / 2] = (j % 2 == 1) ? up[(j - 1) / 2] : down[(j - 1) / 2];
    residuals_into(cases_, point_at(start_, u_, xj.data(), cases_.size()), columns[j].data(), u_.temperature);
  });
  replays_ += 2 * n + 1 - first;
  if (!known) remember(x, columns[0]);
  std::copy(columns[0].begin(), columns[0].end(), residuals);
  for (std::size_t r = 0; r < m; ++r) {
    for (std::size_t i = 0; i < n; ++i) {
      jacobians[0][r * n + i] = (columns[1 + 2 * i][r] - columns[2 + 2 * i][r]) / (up[i] - down[i]);
    }
  }
  jacobian_x_ = x;
  jacobian_residuals_ = columns[0];
  jacobian_.assign(jacobians[0], jacobians[0] + m * n);
  return true;
}

const std::vector<double>* ReplayCost::jacobian_at(const double* x) const {
  const std::size_t n = u_.card_index.size();
  return jacobian_x_.size() == n && std::equal(jacobian_x_.begin(), jacobian_x_.end(), x) ? &jacobian_ : nullptr;
}

const std::vector<double>* ReplayCost::known_residuals(const std::vector<double>& x) const {
  for (const auto& [at, r] : known_) {
    if (at == x) return &r;
  }
  return nullptr;
}

void ReplayCost::remember(const std::vector<double>& x, std::vector<double> r) const {
  if (known_.size() == kKnownPoints) known_.erase(known_.begin());
  known_.emplace_back(x, std::move(r));
}

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

Covariance covariance_at(const std::vector<FitCase>& cases, const std::vector<double>& residuals,
                         const std::vector<double>& jacobian, std::size_t unknowns) {
  const std::size_t m = residuals.size();
  const std::size_t n = unknowns;
  Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> J(
      jacobian.data(), static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(n));
  const Eigen::Map<const Eigen::VectorXd> r(residuals.data(), static_cast<Eigen::Index>(m));
  Covariance c;
  c.rms = rms(residuals);
  // The position rows come first (residuals_into); the few polled
  // temperatures, seconds apart, are taken as independent.
  c.autocorrelation_rows = autocorrelation_time(
      cases, std::vector<double>(residuals.begin(), residuals.begin() + static_cast<std::ptrdiff_t>(position_count(cases))));
  const double dof = std::max<double>(1.0, static_cast<double>(m) - static_cast<double>(n));
  const double sigma2 = static_cast<double>(m) * c.rms * c.rms / dof * c.autocorrelation_rows;
  const Eigen::MatrixXd JtJ = J.transpose() * J;
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(JtJ);
  const Eigen::MatrixXd inverse = cod.pseudoInverse();
  c.cov = inverse * sigma2;
  c.gauss_newton = -(inverse * (J.transpose() * r));
  c.singular = cod.rank() < static_cast<Eigen::Index>(n);
  return c;
}

} // namespace sreh
