// The bands of `size --uncertainty` on the sizing pages (issue 26): a table
// of each figure's nominal value and range over the sampled models, and the
// verdict over all of them (report_parts.hpp).
#include "sizing/report_parts.hpp"

#if SREH_SIZING_WITH_REPORT
#include <fmt/format.h>

#include "sizing/uncertainty.hpp"

namespace sreh::sizing::report_parts {

std::string uncertainty_section(const UncertaintyResult& u, const UncertainFigures& nominal) {
  std::string o = fmt::format("<h2>Over the model's uncertainty</h2>\n<p><span class=\"result {}\">{}</span> "
                              "{} models drawn by a Latin hypercube over the model card's ranges (seed {}); "
                              "{} infeasible, {} with a move that did not complete. The bands cover the nominal "
                              "model and every completed sample; a calibrated model file (--model) narrows them "
                              "(docs/calibration.md).</p>\n",
                              u.feasible_worst_case ? "ok" : "bad",
                              u.feasible_worst_case ? "FEASIBLE IN EVERY SAMPLE" : "NOT FEASIBLE IN EVERY SAMPLE",
                              u.samples, u.seed, u.infeasible_samples, u.incomplete_samples);
  if (u.banded == 0) return o + "<p>No sample completed its moves: no bands.</p>\n";
  o += "<table>\n<tr><th>figure</th><th>nominal</th><th>lowest</th><th>highest</th></tr>\n";
  const auto band_row = [&](const char* name, double value, const Band& b, const char* unit, int decimals) {
    o += fmt::format("<tr><td class=\"l\">{}</td><td>{:.{}f} {}</td><td>{:.{}f}</td><td>{:.{}f}</td></tr>\n", name, value,
                     decimals, unit, b.lo, decimals, b.hi, decimals);
  };
  if (u.cycle_s && nominal.cycle_s) band_row("cycle time", *nominal.cycle_s, *u.cycle_s, "s", 4);
  band_row(u.cycle_s ? "positioning time (worst move)" : "positioning time", nominal.positioning_s, u.positioning_s, "s", 4);
  band_row(u.cycle_s ? "settling time (worst move)" : "settling time", nominal.settling_s, u.settling_s, "s", 4);
  band_row("peak torque", nominal.peak_torque_Nm, u.peak_torque_Nm, "N m", 3);
  band_row("steady temperature", nominal.temperature_C, u.max_temperature_C, "degC", 1);
  o += "</table>\n";
  return o;
}

svg::Band peak_torque_band(const UncertaintyResult& u) {
  return {{}, {}, u.peak_torque_Nm.lo, u.peak_torque_Nm.hi, "peak torque over the sampled models", "#ff7f0e", 0.2};
}

} // namespace sreh::sizing::report_parts
#endif
