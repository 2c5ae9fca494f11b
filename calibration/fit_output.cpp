#include "calibration/fit_output.hpp"

#include <algorithm>
#include <cstdlib>
#include <ctime>
#include <filesystem>

#include <fmt/format.h>

#include "io/figures.hpp"

namespace sreh {
namespace {

const FittedConstant* fitted(const FitResult& fit, const std::string& name) {
  for (const FittedConstant& f : fit.constants) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

// The fitted load is the setup's, not the module's (A-CAL-14): named in a
// comment, never a constant of the file.
std::string load_comment(const FitResult& fit) {
  std::string out;
  for (const FittedConstant& f : fit.constants) {
    if (f.load) {
      out += fmt::format("# The attached load was fitted too ({}: {} g cm^2, stated {}); it belongs to the setup, not\n"
                         "# to the module, and is not written here.\n",
                         f.name, shortest_number(f.value), shortest_number(f.start));
    }
  }
  return out;
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

} // namespace

std::string fit_model_yaml(const FitResult& fit, const ModelCard& base, const std::vector<std::string>& logs,
                           const std::string& date) {
  std::string names;
  for (const std::string& log : logs) {
    names += (names.empty() ? "" : ", ") + std::filesystem::path(log).filename().string();
  }
  std::string out = fmt::format(
      "# Model file written by `sreh-twin calibrate` (issue 26) from {}.\n"
      "# Use it with --model on run, size, sweep, serve. Ranges are the card's; an identified constant\n"
      "# adds its 95 % interval, which uncertainty sizing samples instead (docs/calibration.md).\n"
      "# rms residual {} deg (start {} deg, the log's floor {} deg), {} iterations from {} starts, {}.\n"
      "{}constants:\n",
      names, shortest_number(fit.rms_residual_deg), shortest_number(fit.start_rms_residual_deg),
      shortest_number(fit.floor_rms_deg), fit.iterations, fit.starts,
      !fit.adequate ? "the model does not explain this log" : fit.converged ? "converged" : "NOT converged",
      load_comment(fit));
  for (const ModelConstant& c : fit.card.constants) {
    const ModelConstant* b = base.find(c.name);
    const FittedConstant* f = fitted(fit, c.name);
    if (!f) {
      if (b && *b == c) continue;
      out += fmt::format("  {}: {{value: {}, source: {}, range: [{}, {}]}}\n", c.name, shortest_number(c.value),
                         quoted(c.source), shortest_number(c.range_lo), shortest_number(c.range_hi));
      continue;
    }
    // The card's range stays (issue 36): the interval is a field of its own,
    // written only for an identified constant, and uncertainty sizing
    // samples it instead of the range (A-CAL-5).
    const std::string source = fmt::format("calibrated from {} on {}: 95 % interval [{}, {}]{}", names, date,
                                           shortest_number(f->ci95_lo), shortest_number(f->ci95_hi),
                                           f->identified ? "" : "; not identified (" + f->note + ")");
    std::string interval;
    if (f->identified) {
      interval = fmt::format(", interval: [{}, {}]", shortest_number(std::clamp(f->ci95_lo, c.range_lo, c.value)),
                             shortest_number(std::clamp(f->ci95_hi, c.value, c.range_hi)));
    }
    out += fmt::format("  {}: {{value: {}, source: {}, range: [{}, {}]{}}}\n", c.name, shortest_number(c.value),
                       quoted(source), shortest_number(c.range_lo), shortest_number(c.range_hi), interval);
  }
  return out;
}

nlohmann::json fit_json(const FitResult& fit) {
  nlohmann::json constants = nlohmann::json::object();
  for (const FittedConstant& f : fit.constants) {
    nlohmann::json c{{"value", f.value},           {"start", f.start}, {"ci95", {f.ci95_lo, f.ci95_hi}},
                     {"unit", f.unit},             {"identified", f.identified}};
    if (!f.note.empty()) c["note"] = f.note;
    c["at_bound"] = f.at_bound;
    c["starts_disagree"] = f.starts_disagree;
    if (!f.refits.empty()) c["refits"] = f.refits; // the bootstrap, A-CAL-12
    if (f.load) { // the attached load, A-CAL-14: its start is the stated load
      c["load"] = true;
      c["stated"] = f.start;
    }
    constants[f.name] = c;
  }
  nlohmann::json correlation = nlohmann::json::array();
  for (const auto& row : fit.correlation) correlation.push_back(row);
  nlohmann::json j{{"constants", constants},
          {"rms_residual_deg", fit.rms_residual_deg},
          {"start_rms_residual_deg", fit.start_rms_residual_deg},
          {"iterations", fit.iterations},
          {"converged", fit.converged},
          {"solver", fit.solver_message},
          {"residuals", fit.residuals},
          {"autocorrelation_rows", fit.autocorrelation_rows},
          {"correlation", correlation},
          {"starts", fit.starts},
          {"noise_counts", fit.noise_counts},
          {"floor_rms_deg", fit.floor_rms_deg},
          {"adequate", fit.adequate}};
  if (!fit.adequate) j["inadequacy"] = fit.inadequacy;
  if (fit.temperature_residuals > 0) { // a thermal constant fitted on polled temperatures (A-CAL-9)
    j["temperature_residuals"] = fit.temperature_residuals;
    j["rms_temperature_residual_C"] = fit.rms_temperature_residual_C;
  }
  if (!fit.notes.empty()) j["notes"] = fit.notes;
  io::round_figures(j); // issue 29: 9 significant digits for values, rms at 1e-6 deg
  return j;
}

std::string calibration_date() {
  std::time_t now = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) now = static_cast<std::time_t>(std::strtoll(epoch, nullptr, 10));
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[16];
  std::strftime(buf, sizeof buf, "%Y-%m-%d", &tm);
  return buf;
}

} // namespace sreh
