// The bands of `size --uncertainty` on the sizing pages (issues 26, 35): a
// table of each figure's nominal value and its band over the sampled
// models, the samples that failed grouped by limit, the sampled and the
// fixed constants; and the settling over targets a few counts apart
// (report_parts.hpp). The verdict itself is the page's badge (report_verdict.cpp).
#include "sizing/report_parts.hpp"

#if SREH_SIZING_WITH_REPORT
#include <fmt/format.h>

#include "io/html_page.hpp"
#include "sizing/settling_spread.hpp"
#include "sizing/uncertainty.hpp"

namespace sreh::sizing::report_parts {
namespace {

using io::html_escape;

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s.empty() ? std::string("none") : s;
}

std::string failures_table(const std::vector<FailureGroup>& groups) {
  if (groups.empty()) return {};
  std::string o = "<table id=\"sample-failures\">\n<tr><th class=\"l\">failed limit</th><th>samples</th><th>not completed</th>"
                  "<th class=\"l\">which</th><th class=\"l\">e.g.</th></tr>\n";
  for (const FailureGroup& g : groups) {
    std::string ids;
    for (int k : g.samples) ids += (ids.empty() ? "" : ", ") + std::to_string(k);
    o += fmt::format("<tr><td class=\"l\">{}</td><td>{}</td><td>{}</td><td class=\"l\">{}</td><td class=\"l note\">{}</td></tr>\n",
                     html_escape(g.words), g.samples.size(), g.incomplete, ids, html_escape(g.example));
  }
  return o + "</table>\n";
}

} // namespace

std::string uncertainty_section(const UncertaintyResult& u, const UncertainFigures& nominal) {
  std::string o = fmt::format("<h2>Over the model's uncertainty</h2>\n<p>{} models drawn by a Latin hypercube over the model "
                              "card's ranges (seed {}): {}. A sample whose moves did not complete counts as infeasible; the "
                              "bands cover the nominal model and every completed sample; a calibrated model file (--model) "
                              "narrows them (docs/calibration.md).</p>\n",
                              u.samples, u.seed, html_escape(u.sentence()));
  o += failures_table(u.verdict.failures);
  if (u.robust.searched && !u.robust.nominal.failures.empty()) {
    o += "<p>The nominal optimum's failures:</p>\n" + failures_table(u.robust.nominal.failures);
  }
  if (u.banded == 0) {
    o += "<p>No sample completed its moves: no bands.</p>\n";
  } else {
    o += "<table id=\"uncertainty-bands\">\n<tr><th>figure</th><th>nominal</th><th>lowest</th><th>p5</th><th>median</th><th>p95</th>"
         "<th>highest</th></tr>\n";
    const auto band_row = [&](const char* name, double value, const Band& b, const char* unit, int decimals) {
      o += fmt::format("<tr><td class=\"l\">{}</td><td>{:.{}f} {}</td><td>{:.{}f}</td><td>{:.{}f}</td><td>{:.{}f}</td><td>{:.{}f}</td>"
                       "<td>{:.{}f}</td></tr>\n",
                       name, value, decimals, unit, b.lo, decimals, b.p5, decimals, b.median, decimals, b.p95, decimals, b.hi,
                       decimals);
    };
    if (u.cycle_s && nominal.cycle_s) band_row("cycle time", *nominal.cycle_s, *u.cycle_s, "s", 4);
    band_row(u.cycle_s ? "positioning time (worst move)" : "positioning time", nominal.positioning_s, u.positioning_s, "s", 4);
    band_row(u.cycle_s ? "settling time (worst move)" : "settling time", nominal.settling_s, u.settling_s, "s", 4);
    band_row("peak torque", nominal.peak_torque_Nm, u.peak_torque_Nm, "N m", 3);
    band_row("steady temperature", nominal.temperature_C, u.max_temperature_C, "degC", 1);
    o += "</table>\n";
  }
  o += fmt::format("<p id=\"sampled-constants\">Sampled ({}): {}.</p>\n<p id=\"fixed-constants\">Held at their value, a range of "
                   "one value on the card ({}): {}.</p>\n",
                   u.sampled.size(), html_escape(joined(u.sampled)), u.fixed.size(), html_escape(joined(u.fixed)));
  return o;
}

svg::Band peak_torque_band(const UncertaintyResult& u) {
  return {{}, {}, u.peak_torque_Nm.lo, u.peak_torque_Nm.hi, "peak torque over the sampled models", "#ff7f0e", 0.2};
}

std::string settling_spread_section(const SettlingSpread& s) {
  std::string o = fmt::format("<h2>Settling over targets a few counts apart</h2>\n<p id=\"settling-spread\">The answer's set run "
                              "with the target moved by -{0} .. +{0} position counts ({1} runs{2}). ",
                              s.counts, s.runs, s.incomplete ? fmt::format(", {} not completed", s.incomplete) : "");
  if (!s.settling_s) return o + "No run completed.</p>\n";
  if (!s.chaotic()) {
    o += "The times into the window stay within 1 ms: the single figures hold.</p>\n";
  } else {
    o += "The time into the window changes by more than 1 ms between them (stick-slip near the target): the single run's "
         "figure is one draw of this distribution.</p>\n<table>\n<tr><th>figure</th><th>lowest</th><th>median</th><th>p95</th>"
         "<th>highest</th></tr>\n";
    const auto band_row = [&](const char* name, const std::optional<Band>& b) {
      if (b) o += fmt::format("<tr><td class=\"l\">{} s</td><td>{:.4f}</td><td>{:.4f}</td><td>{:.4f}</td><td>{:.4f}</td></tr>\n", name, b->lo,
                              b->median, b->p95, b->hi);
    };
    band_row("settling time (worst move)", s.settling_s);
    band_row("positioning time (worst move)", s.positioning_s);
    band_row("into the window for good (worst move)", s.in_window_s);
    o += "</table>\n";
  }
  if (s.never_held > 0) {
    o += fmt::format("<p id=\"window-not-held\">{} of {} moves were outside the {:.4f} deg window {}: {}; {}.</p>\n",
                     s.never_held, s.moves, s.tolerance_deg, html_escape(not_held_when(s)),
                     html_escape(hunting_explanation(s)), html_escape(holding_window_text(s)));
  }
  return o;
}

} // namespace sreh::sizing::report_parts
#endif
