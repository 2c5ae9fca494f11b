// Pieces both HTML reports (report.cpp: one move and sweeps;
// cycle_report.cpp: a cycle) are built from, written once (report.cpp).
// Only in builds with reports (SREH_SIZING_WITH_REPORT).
#pragma once
#if SREH_SIZING_WITH_REPORT
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "renders/svg_plot.hpp"
#include "sizing/report.hpp"
#include "sizing/sizing.hpp"

namespace sreh::sizing::report_parts {

// A small fixed palette, one colour per angle / series / move.
const char* colour(std::size_t i);
// One row of a two-column numbers table, escaped.
std::string row(const std::string& name, const std::string& value);
// The page shell (io/html_page.hpp) opened, with `title` as <h1>.
std::string page_head(const std::string& title);
// Writes `html` as dir/index.html atomically (the folder made if needed).
std::filesystem::path write_index(const std::filesystem::path& dir, const std::string& html);

// An empty speed-torque plane (manual 3.5.3): |velocity| in deg/s against
// |motor torque| in N m, both from zero.
svg::Plot speed_torque_plane(const std::string& id, const std::string& title);
// Setpoint and actual position of `rows` against time, s.
svg::Plot position_plot(const std::string& id, const std::vector<TraceRow>& rows);
// The motor's speed-torque capability at `voltage_V` (MotorModel, manual
// 3.5.3), from standstill to `top_factor` x the no-load speed.
svg::Series motor_envelope(const MotorModel& motor, double voltage_V, double top_factor, const std::string& label, const char* color,
                           double width, bool dashed);
// The RMS point (issue 17, RMS torque at the RMS speed) as a series, and
// the torque margin and continuous torque lines (A-SIZE-14) on `plot`.
void add_rms_point(svg::Plot& plot, double rms_speed_dps, double rms_torque_Nm, double torque_capability_Nm,
                   double continuous_torque_Nm);

// What the verdict block shows (issue 29): the figures `size` prints in its
// text and JSON (TraceFigures, the same fields), the answer, and what the
// page adds to them.
struct VerdictInput {
  const TraceFigures* figures = nullptr; // utilisation, supply, reason
  bool feasible = false;                 // the answer `size` prints
  std::string binding_limit;
  double required_thermal_margin_K = 0;
  double ambient_C = 25;
  double speed_dps = 0;  // the fastest set's speed (index 64+n.1)
  double load_gcm2 = 0;  // the heaviest load moved
  // size --uncertainty (issue 35): the badge is the verdict over every
  // sample ("FEASIBLE IN EVERY SAMPLE" or not), its sentence beside it.
  const UncertaintyResult* uncertainty = nullptr;
};

// The block every sizing page opens with (single move, cycle): feasible or
// not, utilisation bars against 100 % (peak torque, RMS torque, thermal,
// speed), the binding limit, the thermal and torque margins, the inertia
// ratio J_load / J_intern and the supply figures (report_verdict.cpp).
std::string verdict_block(const VerdictInput& in);
// The sweep's points (it has no page per point), one row each: the answer,
// the binding limit and the four bars of verdict_block, small; at most
// `max_rows` rows.
std::string verdict_table(const std::vector<std::pair<std::string, VerdictInput>>& points, std::size_t max_rows);

// size --uncertainty on a page (report_uncertainty.cpp, issue 26): the
// nominal figures the bands are read against (a cycle: the worst move's times
// and the cycle time), the section with the table and the verdict over all
// samples, and the peak torque's band for the torque plot.
struct UncertainFigures {
  double positioning_s = 0, settling_s = 0, peak_torque_Nm = 0, temperature_C = 0;
  std::optional<double> cycle_s;
};
std::string uncertainty_section(const UncertaintyResult& u, const UncertainFigures& nominal);
svg::Band peak_torque_band(const UncertaintyResult& u);

// The settling over targets a few counts apart (issue 35,
// report_uncertainty.cpp): median and p95 where it is chaotic, and why a
// window is not held for good.
std::string settling_spread_section(const SettlingSpread& spread);

} // namespace sreh::sizing::report_parts
#endif
