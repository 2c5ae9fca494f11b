// The verdict block of the sizing pages (issue 29): one component for the
// single-move and the cycle page. Its numbers are the TraceFigures fields
// `size` prints in text and JSON (sizing/output.cpp verdict_text), with the
// same rounding; the bars only draw them against their limits.
#include "sizing/report_parts.hpp"

#if SREH_SIZING_WITH_REPORT
#include <algorithm>

#include <fmt/format.h>

#include "device_logic/units.hpp"
#include "io/html_page.hpp"
#include "sizing/limit_names.hpp"
#include "sizing/output.hpp"
#include "sizing/uncertainty.hpp"

namespace sreh::sizing::report_parts {
namespace {

using io::html_escape;

// The bars run from 0 to 125 % so that an overload shows as one.
constexpr double kBarFull_pct = 125.0;

double bar_pos(double pct) { return std::clamp(pct, 0.0, kBarFull_pct) / kBarFull_pct * 100.0; }

// A bar's track: `value_pct` of its scale, green below 85 % of `limit_pct`,
// amber up to it, red past it; a mark at 100 % and one at the limit the
// sizing applies when that is stricter.
std::string track(double value_pct, double limit_pct) {
  const char* cls = value_pct > limit_pct ? "badb" : value_pct > 0.85 * limit_pct ? "warnb" : "okb";
  std::string marks = fmt::format("<div class=\"mark\" style=\"left:{:.2f}%\" title=\"100 %\"></div>", bar_pos(100));
  if (limit_pct < 100) {
    marks += fmt::format("<div class=\"mark req\" style=\"left:{:.2f}%\" title=\"limit {:.0f} %\"></div>", bar_pos(limit_pct), limit_pct);
  }
  return fmt::format("<div class=\"track\"><div class=\"fill {}\" style=\"width:{:.2f}%\"></div>{}</div>", cls, bar_pos(value_pct), marks);
}

std::string bar(const std::string& id, const std::string& name, double value_pct, double limit_pct, const std::string& value,
                const std::string& note) {
  return fmt::format("<tr id=\"{}\"><td class=\"l\">{}</td><td class=\"bar\">{}</td><td>{}</td><td class=\"l note\">{}</td></tr>\n", id,
                     html_escape(name), track(value_pct, limit_pct), html_escape(value), html_escape(note));
}

// The four bar lengths of verdict_block, in % of their scales, and the
// thermal bar's own limit.
struct Bars {
  double peak, rms, thermal, thermal_limit, speed;
};

Bars bars(const VerdictInput& in) {
  const TraceFigures& f = *in.figures;
  // Thermal: the temperature rise used of the rise to the 70 degC warning;
  // its limit is where the required margin starts.
  const double room_K = kTemperatureWarning_C - in.ambient_C;
  return {f.utilisation.peak_torque_pct, f.utilisation.rms_torque_pct,
          room_K > 0 ? 100 * (f.steady_temperature_C - in.ambient_C) / room_K : 100,
          room_K > 0 ? std::max(0.0, 100 * (room_K - in.required_thermal_margin_K) / room_K) : 0.0,
          100 * in.speed_dps / max_speed_dps()};
}

} // namespace

std::string verdict_block(const VerdictInput& in) {
  const TraceFigures& f = *in.figures;
  const Utilisation& u = f.utilisation;
  std::string o = "<section class=\"verdict\" id=\"verdict\">\n";
  if (const UncertaintyResult* over = in.uncertainty) { // one verdict over every sample (issue 35)
    o += fmt::format("<p><span class=\"result {}\" id=\"verdict-answer\">{}</span> <span id=\"verdict-sentence\">{}</span></p>\n",
                     over->feasible_worst_case ? "ok" : "bad",
                     over->feasible_worst_case ? "FEASIBLE IN EVERY SAMPLE" : "NOT FEASIBLE IN EVERY SAMPLE",
                     html_escape(over->sentence()));
    o += fmt::format("<p>On the nominal model: binding limit <b id=\"binding-limit\">{}</b>{}</p>\n", html_escape(limit_in_words(in.binding_limit)),
                     f.feasible || f.reason.empty() ? std::string() : " &mdash; " + html_escape(f.reason));
  } else {
    o += fmt::format("<p><span class=\"result {}\" id=\"verdict-answer\">{}</span> binding limit: <b id=\"binding-limit\">{}</b>{}</p>\n",
                     in.feasible ? "ok" : "bad", in.feasible ? "FEASIBLE" : "NOT FEASIBLE", html_escape(limit_in_words(in.binding_limit)),
                     in.feasible || f.reason.empty() ? std::string() : " &mdash; " + html_escape(f.reason));
  }
  const Bars b = bars(in);
  o += "<table class=\"bars\">\n";
  o += bar("bar-peak", "peak torque", b.peak, 100 * kTorqueMargin, fmt::format("{:.0f} %", u.peak_torque_pct),
           fmt::format("of the capability at speed; feasible up to {:.0f} % (docs/sizing.md, What it reports)", 100 * kTorqueMargin));
  o += bar("bar-rms", "RMS torque", b.rms, 100, fmt::format("{:.0f} %", u.rms_torque_pct),
           fmt::format("of the continuous {:.3f} N m (docs/sizing.md, The thermal model)", f.continuous_torque_Nm));
  o += bar("bar-thermal", "thermal", b.thermal, b.thermal_limit, fmt::format("margin {:.1f} K", u.thermal_margin_K),
           fmt::format("steady {:.1f} degC from {:.1f} degC ambient, of the rise to the 70 degC warning; required margin {:.1f} K",
                       f.steady_temperature_C, in.ambient_C, in.required_thermal_margin_K));
  o += bar("bar-speed", "speed", b.speed, 100, fmt::format("{:.1f} deg/s", in.speed_dps),
           fmt::format("set speed of the module's {:.0f} deg/s (manual 6.2)", max_speed_dps()));
  o += "</table>\n<dl>\n";
  auto item = [&o](const char* id, const std::string& name, const std::string& value) {
    o += fmt::format("<dt>{}</dt><dd id=\"{}\">{}</dd>\n", html_escape(name), id, html_escape(value));
  };
  item("margin-thermal", "thermal margin", fmt::format("{:.1f} K to the 70 degC warning (required {:.1f} K)", u.thermal_margin_K,
                                                       in.required_thermal_margin_K));
  item("margin-torque", "torque margin", fmt::format("{:.0f} % of the capability at speed left (required {:.0f} %)",
                                                     100 - u.peak_torque_pct, 100 * (1 - kTorqueMargin)));
  const double j_intern_gcm2 = kgm2_to_gcm2(kInternalInertia_kgm2);
  item("inertia-ratio", "inertia ratio", fmt::format("J_load / J_intern = {:.2f} ({:.0f} g cm^2 / {:.0f} g cm^2, manual 3.5.4)",
                                                     in.load_gcm2 / j_intern_gcm2, in.load_gcm2, j_intern_gcm2));
  item("supply", "supply", supply_text(f.supply));
  return o + "</dl>\n</section>\n";
}

std::string verdict_table(const std::vector<std::pair<std::string, VerdictInput>>& points, std::size_t max_rows) {
  std::string o = "<table class=\"verdicts\" id=\"verdicts\">\n<tr><th class=\"l\">point</th><th>answer</th><th class=\"l\">binding limit</th>"
                  "<th>peak torque</th><th>RMS torque</th><th>thermal margin</th><th>speed</th></tr>\n";
  for (std::size_t i = 0; i < points.size() && i < max_rows; ++i) {
    const VerdictInput& in = points[i].second;
    const Utilisation& u = in.figures->utilisation;
    const Bars b = bars(in);
    auto cell = [](const std::string& bar_html, const std::string& value) {
      return fmt::format("<td class=\"mini\">{}<span>{}</span></td>", bar_html, html_escape(value));
    };
    o += fmt::format("<tr><td class=\"l\">{}</td><td class=\"{}\">{}</td><td class=\"l\">{}</td>{}{}{}{}</tr>\n", html_escape(points[i].first),
                     in.feasible ? "okc" : "badc", in.feasible ? "feasible" : "NOT", html_escape(limit_in_words(in.binding_limit)),
                     cell(track(b.peak, 100 * kTorqueMargin), fmt::format("{:.0f} %", u.peak_torque_pct)),
                     cell(track(b.rms, 100), fmt::format("{:.0f} %", u.rms_torque_pct)),
                     cell(track(b.thermal, b.thermal_limit), fmt::format("{:.1f} K", u.thermal_margin_K)),
                     cell(track(b.speed, 100), fmt::format("{:.1f} deg/s", in.speed_dps)));
  }
  o += "</table>\n";
  if (points.size() > max_rows) {
    o += fmt::format("<p class=\"note\">The first {} of {} points; the CSV has them all.</p>\n", max_rows, points.size());
  }
  return o;
}

} // namespace sreh::sizing::report_parts
#endif
