#include "calibration/plan.hpp"

#include <array>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "calibration/master_log.hpp"
#include "scenarios/load_file.hpp"
#include "twin/load_builder.hpp"
#include "twin/twin.hpp"

namespace sreh {
namespace {


// The eight parameter sets (manual 6.2): speed, acceleration and jerk
// factor, from a slow constant-speed crawl (friction) to near full speed
// and full acceleration (ringing after the stop), all inside 6.2's ranges.
struct PlanSet {
  double speed_dps;
  double accel_pct;
  double jerk_pct;
  const char* why;
};
constexpr std::array<PlanSet, 8> kSets{{
    {30, 100, 100, "slow constant speed: Coulomb and Stribeck friction"},
    {3000, 100, 100, "fast, full acceleration: the load rings after the stop (stiffness, damping)"},
    {1000, 50, 50, "medium"},
    {300, 20, 100, "slow acceleration: rotor inertia"},
    {4000, 100, 30, "near full speed (manual 3.5.3: 4300 deg/s): viscous friction"},
    {100, 10, 10, "gentle"},
    {2000, 70, 100, "long fast moves"},
    {600, 100, 100, "short sharp moves"},
}};

// Moves: {parameter set, absolute target deg}; each is followed by a hold.
struct PlanMove {
  int set;
  double target_deg;
};
constexpr std::array<PlanMove, 18> kMoves{{
    {1, 90}, {1, 0},     // fast out and back (reversal at rest)
    {4, -120}, {4, 60},  // near full speed both ways
    {2, -45}, {2, 45},
    {3, 0},              // slow acceleration
    {0, 20}, {0, -10},   // crawl both ways: friction
    {5, 30}, {5, 0},
    {6, 170}, {6, -170}, // long moves both ways
    {7, 10}, {7, -10},   // short sharp moves
    {1, 45}, {1, 0},
    {0, 10},
}};
constexpr double kHold_s = 0.15;      // after each move: the load's ringing dies out, friction holds
constexpr double kWithin_s = 5.0;     // generous: the longest move (340 deg at 2000 deg/s) takes ~0.3 s; 20 deg at 30 deg/s ~0.8 s

double load_inertia_gcm2(const PlanRequest& r) {
  if (r.load_gcm2 && !r.load_file.empty()) throw CalibrationInputError("--load-gcm2 and --load: give only one of them");
  if (r.load_gcm2) {
    if (!std::isfinite(*r.load_gcm2) || *r.load_gcm2 < 0 || *r.load_gcm2 > max_load_gcm2()) {
      throw CalibrationInputError(fmt::format("--load-gcm2 {:g}: expected 0 .. {:g} g cm^2 (manual 3.5.6)", *r.load_gcm2,
                                              max_load_gcm2()));
    }
    return *r.load_gcm2;
  }
  if (r.load_file.empty()) throw CalibrationInputError("--plan: give the attached load with --load-gcm2 J or --load LOAD.yaml");
  try {
    TwinConfig c;
    c.load = parse_load_file(r.load_file).load;
    c.record_trace = false;
    return Twin(c).load_inertia_gcm2();
  } catch (const ScenarioError& e) {
    throw CalibrationInputError(fmt::format("--load {}", e.what()));
  } catch (const std::invalid_argument& e) {
    throw CalibrationInputError(fmt::format("--load {}: {}", r.load_file, e.what()));
  }
}

} // namespace

std::string calibration_plan_yaml(const PlanRequest& request) {
  const double load = load_inertia_gcm2(request);
  const long load_raw = std::lround(load);
  std::string y = fmt::format(
      "# Identification program written by `sreh-twin calibrate --plan` (issue 26, docs/calibration.md).\n"
      "# Run it on the module while the master logs its process data (one row per cycle:\n"
      "# t_s,pd_out,pd_in[,temperature_C]), then:\n"
      "#   sreh-twin calibrate LOG.csv --setup THIS.yaml --load-gcm2 {} --out fit.yaml\n"
      "# With the twin: sreh-twin run THIS.yaml --master-log LOG.csv\n"
      "# Safe for the module: speeds, accelerations and jerks inside manual 6.2, every set's configured\n"
      "# load (64..71.4) the attached one, targets within +-180 deg of the start; the PLC writes the\n"
      "# parameter sets once before the log starts (calibrate --setup replays them).\n"
      "name: \"calibration plan: {} g cm^2\"\n"
      "load:\n  inertia_gcm2: {}\n",
      load_raw, load_raw, load_raw);
  if (!request.load_file.empty()) {
    y += fmt::format("# the load of {} (its inertia about the axis)\n",
                     std::filesystem::path(request.load_file).filename().string());
  }
  if (request.mounting_tilt_deg != 0) y += fmt::format("mounting: {{tilt_deg: {}}}\n", request.mounting_tilt_deg);
  y += "device:\n  isdu:\n";
  for (std::size_t n = 0; n < kSets.size(); ++n) {
    const PlanSet& s = kSets[n];
    const int index = 64 + static_cast<int>(n);
    y += fmt::format("    # set {}: {} deg/s, {} %, jerk {} %: {}\n", n, s.speed_dps, s.accel_pct, s.jerk_pct, s.why);
    y += fmt::format("    - {{index: {}, subindex: 1, value: {}}}\n", index, std::lround(s.speed_dps * 10));
    y += fmt::format("    - {{index: {}, subindex: 2, value: {}}}\n", index, std::lround(s.accel_pct * 10));
    y += fmt::format("    - {{index: {}, subindex: 3, value: {}}}\n", index, std::lround(s.jerk_pct * 10));
    y += fmt::format("    - {{index: {}, subindex: 4, value: {}}}\n", index, load_raw);
  }
  y += "steps:\n"
       "  - pd: {motor_on: 1}\n"
       "  - wait_until: {state: Ready, within_s: 0.1}\n"
       "  - wait_s: 0.1\n";
  for (const PlanMove& m : kMoves) {
    y += fmt::format("  - pd: {{target_deg: {}, parameter_set: {}, move: 1}}\n", m.target_deg, m.set);
    y += fmt::format("  - wait_until: {{state: Done, within_s: {}}}\n", kWithin_s);
    y += "  - pd: {move: 0}\n";
    y += fmt::format("  - wait_s: {}\n", kHold_s);
    y += "  - isdu_read: {index: 112}   # temperature, logged in the master log's temperature_C\n";
  }
  y += "  - pd: {motor_on: 0}\n"
       "  - wait_s: 0.02\n"
       "expect:\n";
  y += fmt::format("  moves: {}\n  moves_completed: {}\n", kMoves.size(), kMoves.size());
  return y;
}

} // namespace sreh
