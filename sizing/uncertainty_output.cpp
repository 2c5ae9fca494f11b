// The verdict of `size --uncertainty` in words, as text and JSON (issue 35):
// one sentence that text, JSON, report and the exit code all follow.
#include <cmath>

#include <fmt/format.h>

#include "sizing/output.hpp"
#include "sizing/uncertainty.hpp"

namespace sreh::sizing {
namespace {

std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

std::string groups_text(const std::vector<FailureGroup>& groups) {
  std::vector<std::string> parts;
  for (const FailureGroup& g : groups) {
    std::string p = fmt::format("{} in {}", g.words, g.samples.size());
    if (g.incomplete > 0) p += fmt::format(", {} of them not completed", g.incomplete);
    parts.push_back(std::move(p));
  }
  return join(parts, "; ");
}

std::string setting_text(const MotionSetting& s) {
  return fmt::format("{:.1f} deg/s, {:.1f} %, {:.1f} %", s.speed_dps, s.accel_pct, s.jerk_pct);
}

nlohmann::json band_json(const UncertaintyResult& u, const Band& b, bool is_time) {
  if (u.banded == 0) return nullptr;
  const auto r = [is_time](double v) { return is_time ? ns_rounded(v) : v; };
  return {{"lo", r(b.lo)}, {"p5", r(b.p5)}, {"median", r(b.median)}, {"p95", r(b.p95)}, {"hi", r(b.hi)}};
}

nlohmann::json failures_json(const std::vector<FailureGroup>& groups) {
  nlohmann::json j = nlohmann::json::array();
  for (const FailureGroup& g : groups) {
    j.push_back({{"limit", g.limit}, {"words", g.words}, {"samples", g.samples}, {"incomplete", g.incomplete},
                 {"example", g.example}});
  }
  return j;
}

std::string band_line(const char* name, const Band& b, const char* unit, int decimals) {
  return fmt::format("  {:<20}median {:.{}f} {}, p5 .. p95 {:.{}f} .. {:.{}f}, min .. max {:.{}f} .. {:.{}f}\n", name,
                     b.median, decimals, unit, b.p5, decimals, b.p95, decimals, b.lo, decimals, b.hi, decimals);
}

} // namespace

std::string limit_words(const std::string& limit) {
  if (limit == "torque_at_speed") return fmt::format("peak torque above {:.0f} % of the capability at speed", 100 * kTorqueMargin);
  if (limit == "tracking") return fmt::format("tracking error above {:.0f} % of its limit (index 87.1)", 100 * kTrackingMargin);
  if (limit == "temperature") return "steady temperature inside the margin below the 70 degC warning";
  if (limit == "settling") return "not settled in the tolerance window (settling timeout 114.8, or left it after Done 115.3)";
  if (limit == "voltage") return "motor voltage outside its window (114.4 / 115.2)";
  if (limit == "switch_on") return "the motor did not switch on";
  if (limit == "max_positioning") return "positioning time above the target";
  if (limit == "max_cycle") return "cycle time above the target";
  return "a device error ended the run";
}

std::string SampleVerdict::sentence() const {
  std::string s = feasible == samples
                      ? fmt::format("feasible in all {} samples", samples)
                      : fmt::format("feasible in {} of {} samples: {} ({})", feasible, samples,
                                    feasible > 0 ? "at risk" : "not feasible", groups_text(failures));
  return nominal_feasible ? s : "not feasible on the nominal model; " + s;
}

std::string RobustAnswer::sentence() const {
  const std::string nominal_text = fmt::format("the nominal optimum ({}; positioning {:.1f} ms) is {}",
                                               setting_text(nominal_setting), nominal_positioning_s * 1e3, nominal.sentence());
  if (!found) {
    return "no set on the search grid is feasible in every sample" +
           (slowest_fails.empty() ? std::string() : " (not even the slowest: " + slowest_fails + ")") + "; " + nominal_text;
  }
  return fmt::format("the {} set feasible in every sample is recommended, {:.1f} % slower than the nominal optimum; {}",
                     objective == "gentlest" ? "gentlest" : "fastest", slower_pct, nominal_text);
}

std::string UncertaintyResult::sentence() const {
  if (!robust.searched) return verdict.sentence();
  return verdict.sentence() + "; " + robust.sentence();
}

void add_uncertainty_json(nlohmann::json& json, const UncertaintyResult& u) {
  auto ns = [](double v) { return ns_rounded(v); };
  auto pair = [&](const Band& b, bool is_time) {
    return u.banded ? nlohmann::json::array({is_time ? ns(b.lo) : b.lo, is_time ? ns(b.hi) : b.hi}) : nlohmann::json();
  };
  json["positioning_s_range"] = pair(u.positioning_s, true);
  json["settling_s_range"] = pair(u.settling_s, true);
  json["peak_torque_Nm_range"] = pair(u.peak_torque_Nm, false);
  json["max_temperature_C_range"] = pair(u.max_temperature_C, false);
  if (u.cycle_s) json["cycle_s_range"] = pair(*u.cycle_s, true);
  json["feasible_worst_case"] = u.feasible_worst_case;
  json["verdict"] = u.sentence();
  nlohmann::json bands = {{"positioning_s", band_json(u, u.positioning_s, true)},
                          {"settling_s", band_json(u, u.settling_s, true)},
                          {"peak_torque_Nm", band_json(u, u.peak_torque_Nm, false)},
                          {"max_temperature_C", band_json(u, u.max_temperature_C, false)}};
  if (u.cycle_s) bands["cycle_s"] = band_json(u, *u.cycle_s, true);
  nlohmann::json robust = {{"searched", u.robust.searched}};
  if (u.robust.searched) {
    robust["found"] = u.robust.found;
    robust["objective"] = u.robust.objective;
    robust["slower_pct"] = u.robust.found ? nlohmann::json(u.robust.slower_pct) : nlohmann::json();
    robust["slowest_fails"] = u.robust.slowest_fails.empty() ? nlohmann::json() : nlohmann::json(u.robust.slowest_fails);
    robust["nominal_optimum"] = {{"speed_dps", u.robust.nominal_setting.speed_dps},
                                 {"accel_pct", u.robust.nominal_setting.accel_pct},
                                 {"jerk_pct", u.robust.nominal_setting.jerk_pct},
                                 {"positioning_s", ns(u.robust.nominal_positioning_s)},
                                 {"cycle_s", ns(u.robust.nominal_cycle_s)},
                                 {"feasible_samples", u.robust.nominal.feasible},
                                 {"verdict", u.robust.nominal.sentence()},
                                 {"failures", failures_json(u.robust.nominal.failures)}};
  }
  json["uncertainty"] = {{"samples", u.samples},
                         {"seed", u.seed},
                         {"sampling", "latin_hypercube"},
                         {"sampled", u.sampled},
                         {"fixed", u.fixed},
                         {"nominal_feasible", u.verdict.nominal_feasible},
                         {"feasible_samples", u.verdict.feasible},
                         {"infeasible_samples", u.infeasible_samples},
                         {"incomplete_samples", u.incomplete_samples},
                         {"bands", bands},
                         {"failures", failures_json(u.verdict.failures)},
                         {"robust", robust}};
}

std::string uncertainty_text(const UncertaintyResult& u) {
  std::string s = fmt::format("Over the model's uncertainty: {} models drawn by a Latin hypercube over the model card's "
                              "ranges (seed {})\n",
                              u.samples, u.seed);
  s += fmt::format("  verdict           {}\n", u.sentence());
  if (u.banded == 0) {
    s += "  bands             none: no sample completed its moves\n";
  } else {
    s += fmt::format("  bands over the nominal and the completed samples ({} runs):\n", u.banded);
    if (u.cycle_s) s += band_line("cycle", *u.cycle_s, "s", 4);
    s += band_line(u.cycle_s ? "positioning (worst)" : "positioning time", u.positioning_s, "s", 4);
    s += band_line(u.cycle_s ? "settling (worst)" : "settling time", u.settling_s, "s", 4);
    s += band_line("peak torque", u.peak_torque_Nm, "N m", 3);
    s += band_line("steady temperature", u.max_temperature_C, "degC", 1);
  }
  for (const FailureGroup& g : u.verdict.failures) {
    std::vector<std::string> ids;
    for (int k : g.samples) ids.push_back(std::to_string(k));
    s += fmt::format("  failed            {}: sample{} {} (e.g. {})\n", g.words, g.samples.size() == 1 ? "" : "s",
                     join(ids, ", "), g.example);
  }
  s += fmt::format("  sampled ({})      {}\n", u.sampled.size(), join(u.sampled, ", "));
  s += fmt::format("  held ({})         {}\n", u.fixed.size(),
                   u.fixed.empty() ? std::string("none") : join(u.fixed, ", ") + " (a range of one value on the card)");
  return s;
}

} // namespace sreh::sizing
