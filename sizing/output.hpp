// What `sreh-twin size` prints: one JSON object (interfaces.md) or a
// readable summary, and the ISDU writes of the recommended set.
#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "sizing/sizing.hpp"

namespace sreh::sizing {

struct UncertaintyResult; // sizing/uncertainty.hpp
struct SettlingSpread;    // sizing/settling_spread.hpp

// What `size` adds to its answer when asked (issue 35): the verdict over
// the sampled models (--uncertainty) and the settling over targets a few
// counts apart. With an uncertainty result the answer's `feasible`, its
// text and the exit code are the verdict over every sample.
struct AnswerExtras {
  const UncertaintyResult* uncertainty = nullptr;
  const SettlingSpread* spread = nullptr;
};

// "isdu_write index 65 sub 1 value 30000  # speed 3000.0 deg/s"
std::string isdu_write_line(const IsduWrite& w);

// Simulated times are whole physics steps: rounded to the nanosecond so that
// JSON carries no float noise (0.36250000000000004 -> 0.3625; issue 16).
double ns_rounded(double v);
nlohmann::json optional_number(const std::optional<double>& v); // null when none
// Times of a run whose moves did not all complete are null (not meaningful).
nlohmann::json time_if(bool completed, double v);
std::string duration_text(const std::optional<double>& s); // "never", "42 s", "3.5 min", "2.1 h"

// The figures both JSON objects (size, size --cycle) carry: torque,
// tracking, temperature, utilisation, supply, reason (not feasible /
// binding_limit: a search answers those for itself).
void put_figures_json(nlohmann::json& j, const TraceFigures& f, double required_thermal_margin_K);
nlohmann::json json_utilisation(const Utilisation& u, double required_thermal_margin_K);
nlohmann::json json_supply(const SupplyFigures& s);
// One parameter set: number, speed/acceleration/jerk, load, window, ISDU writes.
nlohmann::json json_parameter_set(const ParameterSetValues& s);

// The summary's lines both texts share.
std::string tracking_text(const TraceFigures& f);
// "peak 1.20 A, RMS 0.80 A, regenerated ...": the supply line of the text
// and of the pages' verdict block (one wording, issue 29).
std::string supply_text(const SupplyFigures& s);
// Utilisation, supply, binding limit, feasible (with the reason); with
// `u` the feasible line is the verdict over the samples.
std::string verdict_text(const TraceFigures& f, double required_thermal_margin_K, const std::string& binding_limit,
                         bool feasible, const UncertaintyResult* u = nullptr);

// The JSON object of interfaces.md (`size --json`): travel_s, settling_s,
// positioning_s, cycle_s, cycles_per_min, peak_torque_Nm, rms_torque_Nm,
// torque_capability_Nm, steady_temperature_C, time_to_warning_s (null if
// never), feasible, reason, recommended{...}, moves[...], request{...}.
// With extras also `feasible_nominal`, the uncertainty keys
// (add_uncertainty_json) and `settling_spread`.
nlohmann::json to_json(const SizingRequest& request, const SizingResult& result, const AnswerExtras& extras = {});

// The human summary, several lines ending in a newline.
std::string summary_text(const SizingRequest& request, const SizingResult& result, const AnswerExtras& extras = {});

} // namespace sreh::sizing
