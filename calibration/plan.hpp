// `sreh-twin calibrate --plan OUT.yaml` (issue 26): the identification
// program, a scenario a PLC can run on the real module (process data and
// ISDU only) while its master logs: moves of several amplitudes, speeds and
// accelerations both ways, reversals, slow constant-speed runs (friction),
// fast stops with the load ringing (stiffness, damping), holds, and the
// temperature polled over ISDU. Safe: every speed, acceleration and jerk a
// parameter set the manual allows (6.2), the configured load right (3.5.6),
// targets within +-180 deg of the start.
#pragma once
#include <optional>
#include <string>

namespace sreh {

struct PlanRequest {
  std::optional<double> load_gcm2;
  std::string load_file;
  double mounting_tilt_deg = 0;
};

// The scenario as YAML. Throws CalibrationInputError for a bad load.
std::string calibration_plan_yaml(const PlanRequest& request);

} // namespace sreh
