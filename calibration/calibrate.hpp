// `sreh-twin calibrate` and Python `sreh_twin.calibrate(...)`, one code path
// (issue 26): read and check every input first (CalibrationInputError, exit
// 2, before any long work), then fit.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "calibration/fit.hpp"

namespace sreh {

struct CalibrateRequest {
  std::vector<std::string> logs;   // master logs (calibration/master_log.hpp)
  std::optional<double> load_gcm2; // the attached load: an inertia ...
  std::string load_file;           // ... or a load file (scenario `load:` syntax)
  std::string setup;               // optional scenario: world and start-up ISDU writes (A-CAL-2)
  std::string model;               // optional start model file (--model)
  std::vector<std::string> fit;    // constants to fit; empty: default_fit_names()
  FitOptions options;
};

struct CalibrateOutcome {
  FitResult fit;
  ModelCard start;
  std::vector<FitCase> cases; // the logs as read, with their setups (for the report)
  std::string model_yaml; // FIT.yaml
};

// Everything read and checked, nothing fitted yet.
struct CalibrateInputs {
  std::vector<FitCase> cases;
  ModelCard start;
};
CalibrateInputs read_calibrate_inputs(const CalibrateRequest& request);

CalibrateOutcome calibrate(const CalibrateRequest& request);

} // namespace sreh
