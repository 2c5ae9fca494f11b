// What a fit gives back (issue 26): FIT.yaml, a model file `--model` reads
// (twin/model_card.hpp), and the `--json` object.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calibration/fit.hpp"

namespace sreh {

// The constants that differ from `base` (the start file's overrides) and
// every fitted one: value, `source: calibrated from LOG... on DATE`, and as
// range the 95 % interval inside the card's range, so that uncertainty
// sizing with this file samples what the data left open (A-CAL-5).
std::string fit_model_yaml(const FitResult& fit, const ModelCard& base, const std::vector<std::string>& logs,
                           const std::string& date);

// {"constants": {NAME: {value, start, ci95, unit, identified[, note]}}, rms_residual_deg,
//  start_rms_residual_deg, iterations, converged, solver, residuals}
nlohmann::json fit_json(const FitResult& fit);

// Today's date (UTC, YYYY-MM-DD), or that of SOURCE_DATE_EPOCH when set, so
// that a calibration can be repeated byte for byte.
std::string calibration_date();

} // namespace sreh
