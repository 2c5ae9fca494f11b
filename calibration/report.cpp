#include "calibration/report.hpp"

#if SREH_CALIBRATION_WITH_REPORT
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "calibration/master_log.hpp"
#include "calibration/replay.hpp"
#include "io/atomic_file.hpp"
#include "calibration/fit_adequacy.hpp"
#include "io/html_page.hpp"
#include "io/output_path.hpp"
#include "io/provenance.hpp"
#include "renders/figure.hpp"
#include "renders/svg_plot.hpp"
#include "twin/load_builder.hpp"

namespace sreh {
namespace {

constexpr const char* kLogged = "#333333";
constexpr const char* kStart = "#ff7f0e";
constexpr const char* kFitted = "#1f77b4";

std::string esc(const std::string& s) { return io::html_escape(s); }

struct Replayed {
  std::vector<double> t_s, logged_deg, start_deg, fitted_deg;
  std::vector<double> t_temperature_s, logged_C, fitted_C;
};

// The start card on the stated setup, the fitted card on the fitted one.
Replayed replay_both(const FitCase& c, const FitCase& fitted_case, const ModuleModel& start, const ModuleModel& fitted) {
  const ReplayTrack a = replay(c.setup, start, c.log);
  const ReplayTrack b = replay(fitted_case.setup, fitted, c.log);
  Replayed r;
  for (std::size_t k = 0; k < c.log.rows.size(); ++k) {
    const MasterLogRow& row = c.log.rows[k];
    r.t_s.push_back(row.t_s);
    r.logged_deg.push_back(logged_position_deg(row.pd_in));
    r.start_deg.push_back(a.position_deg[k]);
    r.fitted_deg.push_back(b.position_deg[k]);
    if (row.temperature_C) {
      r.t_temperature_s.push_back(row.t_s);
      r.logged_C.push_back(*row.temperature_C);
      r.fitted_C.push_back(b.temperature_C[k]);
    }
  }
  return r;
}

std::vector<double> minus(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> d(a.size());
  for (std::size_t k = 0; k < a.size(); ++k) d[k] = a[k] - b[k];
  return d;
}

double rms(const std::vector<double>& v) {
  double sum = 0;
  for (double x : v) sum += x * x;
  return v.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(v.size()));
}

std::string log_section(std::size_t i, const FitCase& c, const Replayed& r) {
  const std::vector<double> start_error = minus(r.start_deg, r.logged_deg);
  const std::vector<double> fitted_error = minus(r.fitted_deg, r.logged_deg);
  std::string o = fmt::format("<h2>Log {}: {}</h2>\n<p>{} rows over {:.3f} s; rms error {:.5f} deg with the start card, "
                              "{:.5f} deg fitted.</p>\n",
                              i + 1, esc(c.log.path), c.log.rows.size(), r.t_s.empty() ? 0.0 : r.t_s.back() - r.t_s.front(),
                              rms(start_error), rms(fitted_error));
  svg::Plot position;
  position.id = fmt::format("log{}_position", i + 1);
  position.title = "Position: logged and simulated";
  position.x = {"time", "s", {}, {}};
  position.y = {"position", "deg", {}, {}};
  position.series = {{"logged (process data)", r.t_s, r.logged_deg, kLogged, 2.5},
                     {"twin, start card", r.t_s, r.start_deg, kStart, 1.2, true},
                     {"twin, fitted card", r.t_s, r.fitted_deg, kFitted, 1.2}};
  o += report::figure(position);
  svg::Plot error;
  error.id = fmt::format("log{}_error", i + 1);
  error.title = "Error: simulated - logged position";
  error.x = position.x;
  error.y = {"error", "deg", {}, {}};
  error.series = {{"start card", r.t_s, start_error, kStart, 1.2, true}, {"fitted card", r.t_s, fitted_error, kFitted, 1.2}};
  error.hlines = {{kWireCount_deg, "+-1 wire count (0.0055 deg)", "#2ca02c", true, false},
                  {-kWireCount_deg, "", "#2ca02c", true, false}};
  o += report::figure(error);
  if (!r.logged_C.empty()) {
    svg::Plot temperature;
    temperature.id = fmt::format("log{}_temperature", i + 1);
    temperature.title = "Temperature: polled over ISDU and simulated";
    temperature.x = position.x;
    temperature.y = {"temperature", "degC", {}, {}};
    temperature.series = {{"logged", r.t_temperature_s, r.logged_C, kLogged, 1.5, false, true},
                          {"twin, fitted card", r.t_temperature_s, r.fitted_C, kFitted, 1.2}};
    o += report::figure(temperature);
  }
  return o;
}

std::string constants_table(const ModelCard& start, const FitResult& fit) {
  std::string o = "<h2>Constants</h2>\n<table>\n<tr><th>constant</th><th>unit</th><th>start</th><th>fitted</th>"
                  "<th>change</th><th>95 % interval</th><th>identified</th></tr>\n";
  for (const FittedConstant& f : fit.constants) {
    const ModelConstant* s = f.load ? nullptr : start.find(f.name); // the load's start is the stated load
    const double change_pct = f.start != 0 ? 100.0 * (f.value - f.start) / f.start : 0.0;
    o += fmt::format("<tr><td class=\"l\">{}</td><td>{}</td><td>{:.6g}</td><td>{:.6g}</td><td>{:+.1f} %</td>"
                     "<td>{:.6g} .. {:.6g}</td><td>{}</td></tr>\n",
                     esc(f.name) + (f.load ? " (the attached load; start: the stated load)" : ""), esc(f.unit),
                     s ? s->value : f.start, f.value, change_pct, f.ci95_lo, f.ci95_hi,
                     f.identified ? "<span class=\"result ok\">yes</span>"
                                  : "<span class=\"result bad\">no</span> " + esc(f.note));
  }
  return o + "</table>\n";
}

std::string correlation_table(const FitResult& fit) {
  if (fit.correlation.size() != fit.constants.size() || fit.constants.size() < 2) return "";
  std::string o = fmt::format("<h2>Correlation of the fitted constants</h2>\n<p>|r| above {} (bold) means the data "
                              "trade one constant against the other: excite more (another amplitude, speed or a hold) "
                              "or fit fewer.</p>\n<table>\n<tr><th></th>",
                              kStrongCorrelation);
  for (const FittedConstant& f : fit.constants) o += "<th>" + esc(f.name) + "</th>";
  o += "</tr>\n";
  for (std::size_t i = 0; i < fit.constants.size(); ++i) {
    o += "<tr><td class=\"l\">" + esc(fit.constants[i].name) + "</td>";
    for (std::size_t j = 0; j < fit.constants.size(); ++j) {
      const double r = fit.correlation[i][j];
      const bool strong = i != j && std::abs(r) > kStrongCorrelation;
      o += strong ? fmt::format("<td><b>{:+.2f}</b></td>", r) : fmt::format("<td>{:+.2f}</td>", r);
    }
    o += "</tr>\n";
  }
  return o + "</table>\n";
}

} // namespace

bool calibration_reports_available() { return true; }

namespace {

// Where the page came from (issue 37): command line, version, date, the logs and their setups.
std::string with_provenance(const std::string& body, const std::vector<FitCase>& cases) {
  std::vector<std::pair<std::string, std::string>> in;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const TwinConfig& c = cases[i].setup.config;
    in.push_back({fmt::format("log {}", i + 1), fmt::format("{} ({} rows): load {}, axis tilted {} deg from vertical, {} V, "
                                                            "ambient {} degC", cases[i].log.path, cases[i].log.rows.size(),
                                                            describe_load(c.load), c.mounting_tilt_deg, c.supply.voltage_V,
                                                            c.thermal.ambient_C)});
  }
  return io::with_provenance(body, io::report_provenance(std::move(in)));
}

} // namespace

std::filesystem::path write_calibration_report(const std::filesystem::path& dir, const std::vector<FitCase>& cases,
                                               const ModelCard& start, const FitResult& fit) {
  const ModuleModel start_module = start.module_model();
  const ModuleModel fitted_module = fit.card.module_model();
  const std::vector<FitCase> fitted_cases = with_fitted_load(cases, fit.load_scale); // the fitted load (A-CAL-14)
  const std::string title = fmt::format("Calibration: {} log{}", cases.size(), cases.size() == 1 ? "" : "s");
  std::string body = fmt::format("<h1>{}</h1>\n", esc(title));
  const bool ok = fit.converged && fit.adequate;
  const char* verdict = !fit.adequate ? "THE MODEL DOES NOT EXPLAIN THIS LOG" : fit.converged ? "CONVERGED" : "NOT CONVERGED";
  body += fmt::format("<p><span class=\"result {}\">{}</span> after {} iterations from {} starts: rms error {:.5f} deg "
                      "(start card {:.5f} deg; the log's floor {:.5f} deg, from the wire's quantisation and {:.2f} "
                      "counts of noise) over {} logged rows. Solver: {}</p>\n",
                      ok ? "ok" : "bad", verdict, fit.iterations, fit.starts, fit.rms_residual_deg, fit.start_rms_residual_deg,
                      fit.floor_rms_deg, fit.noise_counts, fit.residuals, esc(fit.solver_message));
  if (!fit.adequate) body += fmt::format("<p class=\"note\">{}</p>\n", esc(fit.inadequacy));
  for (const std::string& note : fit.notes) body += fmt::format("<p class=\"note\">{}</p>\n", esc(note));
  body += constants_table(start, fit) + correlation_table(fit);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    body += log_section(i, cases[i], replay_both(cases[i], fitted_cases[i], start_module, fitted_module));
  }
  io::make_output_folder(dir.string());
  const std::filesystem::path index = dir / "index.html";
  io::write_file_atomic(index.string(),
                        [&](std::ostream& out) { out << io::html_page(title, report::page_head(), with_provenance(body, cases)); });
  return index;
}

} // namespace sreh

#else // built without renders

namespace sreh {

bool calibration_reports_available() { return false; }

std::filesystem::path write_calibration_report(const std::filesystem::path&, const std::vector<FitCase>&, const ModelCard&,
                                               const FitResult&) {
  return {};
}

} // namespace sreh

#endif
