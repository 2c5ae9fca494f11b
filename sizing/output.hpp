// What `sreh-twin size` prints: one JSON object (interfaces.md) or a
// readable summary, and the ISDU writes of the recommended set.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "sizing/sizing.hpp"

namespace sreh::sizing {

// "isdu_write index 65 sub 1 value 30000  # speed 3000.0 deg/s"
std::string isdu_write_line(const IsduWrite& w);

// The JSON object of interfaces.md (`size --json`): travel_s, settling_s,
// positioning_s, cycle_s, cycles_per_min, peak_torque_Nm, rms_torque_Nm,
// torque_capability_Nm, steady_temperature_C, time_to_warning_s (null if
// never), feasible, reason, recommended{...}, moves[...], request{...}.
nlohmann::json to_json(const SizingRequest& request, const SizingResult& result);

// The human summary, several lines ending in a newline.
std::string summary_text(const SizingRequest& request, const SizingResult& result);

} // namespace sreh::sizing
