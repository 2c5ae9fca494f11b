// PerfectCycle-style sizing (issue 8, manual 3.5.1): one move of A deg back
// and forth with a dwell, evaluated by running the twin (a factory-new module
// with the load, the parameter set written over ISDU, motor on, moves through
// process data). Travel time comes from the planner, settling and
// positioning from the simulation, torque from the trace, temperature from
// the twin's thermal model fed with the cycle's mean loss.
// Constants the manual does not give: docs/assumptions/sizing.md (A-SIZE-*).
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "device_logic/parameter_ids.hpp"
#include "scenarios/world.hpp"
#include "twin/trace.hpp"
#include "twin/twin.hpp"

namespace sreh::sizing {

// Input outside the module's limits (the CLI turns it into exit code 2).
class SizingInputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Speed, acceleration and jerk of a motion parameter set (manual 3.5.3-3.5.5),
// display units.
struct MotionSetting {
  double speed_dps = 3000.0; // factory default of sets 1..7 (manual 6.2)
  double accel_pct = 100.0;
  double jerk_pct = 100.0;
};

// The settling rows every motion set repeats (manual 3.5.7, 6.2: 64+n.5..7),
// written alike to every set a sizing uses; one spec for the command line,
// single moves and cycles.
struct SettlingSpec {
  // 64+n.5: the manual's factory default 0.1 deg, as users give it; the
  // table keeps it as 146 counts (0.10025 deg), which 0.1 rounds to.
  double tolerance_deg = 0.1;
  double wait_ms = display_default(param::MotionSet(0).waiting_time); // 64+n.6, the table's default
  std::optional<double> timeout_ms; // 64+n.7; unset: A-SIZE-4
};

struct SizingRequest {
  double angle_deg = 90.0;       // move distance; the cycle goes 0 -> A -> 0
  // Load, supply (16..32 V, the index 85 window, A-SIZE-2; the source
  // model, A-SIZE-15), ambient, mounting (A-TWIN-24) and the model card
  // (`--model FILE`, issue 25): the same world a scenario runs in.
  WorldSetup world;
  std::string load_name;         // shown with the load (issue 39): a load file's name: and file; empty: --load-gcm2
  double dwell_s = 0.0;          // pause after each move (after Done)
  SettlingSpec settling;
  int parameter_set = 1;         // which of 64..71 the writes and moves use
  std::optional<MotionSetting> setting; // given: evaluate it; unset: recommend one
  int cycles = 2;                // back-and-forth cycles simulated (A-SIZE-3)
  bool keep_trace = false;       // keep the chosen evaluation's trace (reports)
  // Required distance of the steady temperature below the 70 degC warning
  // (manual 7.3 115.1), K (A-SIZE-5).
  double thermal_margin_K = 5.0;
  // Targets (issue 17): given one, the search looks for the gentlest set
  // (lowest RMS torque) meeting it; an explicit set must meet it to be feasible.
  std::optional<double> max_positioning_ms; // worst move's positioning time
  std::optional<double> max_cycle_ms;       // cycle_s (2 positionings + 2 dwells)
  // IO-Link cycles per move the PLC handshake adds to the cycle (A-SIZE-16):
  // Move reaches the device (1), Done comes back (1), the PLC reacts (1),
  // Move stays low one cycle before the next command (manual 3.2 T7) (1).
  int handshake_cycles = 4;
  // Called as each simulation starts (the CLI's progress line, issue 39);
  // from several threads at once with --uncertainty. Empty: nothing.
  std::function<void()> on_simulation;
  // Threads the gentlest search may use (> 1: it evaluates the candidate it
  // would run next on a second thread, issue 37); the answer does not
  // depend on it. 1 where the caller runs requests side by side (sweep).
  int search_threads = 1;
};

// What the motor supply sees (issue 17, A-SIZE-15), from the trace.
struct SupplyFigures {
  double peak_current_A = 0;  // drawn from the source (regeneration counts as 0 drawn)
  double rms_current_A = 0;   // over the last simulated cycle
  double regen_energy_J = 0;  // the largest energy fed back in one braking
  double peak_bus_V = 0;      // highest bus voltage seen
  double bus_max_V = 0;       // configured upper window, index 85.2
  bool overvoltage_advice = false; // manual 7.2 114.4 cause 2: capacity or a chopper
};

// Utilisation as the pro tools show it (issue 17).
struct Utilisation {
  double peak_torque_pct = 0;  // max over samples of |torque| / capability at that speed and voltage
  double rms_torque_pct = 0;   // RMS torque / continuous torque (A-SIZE-14)
  double thermal_margin_K = 0; // 70 degC warning - steady temperature
};

// One ISDU write of the parameter set, raw wire value (manual 6.2).
struct IsduWrite {
  uint16_t index = 0;
  uint8_t subindex = 0;
  int64_t value = 0;
  std::string comment; // "speed 3000.0 deg/s"
};

// A complete parameter set as written to the device.
struct ParameterSetValues {
  int set = 1;
  MotionSetting setting;    // display values as the device reads them back (raw x 0.1)
  MotionSetting tidy;       // the same as raw / 10: 81.3 rather than 81.30000000000001, for output
  double load_gcm2 = 0;     // configured load (64+n.4)
  double tolerance_deg = 0; // after raw rounding
  double wait_ms = 0;
  double timeout_ms = 0;
  double voltage_V = 24;    // only for the index 85 writes
  std::vector<IsduWrite> writes; // 64+n.1..8, plus 85.x where the voltage needs it
};

struct MoveResult {
  double target_deg = 0;
  double travel_s = 0;      // planner (exact), manual 3.5.2 (1)
  double simulated_travel_s = -1; // MoveRecord: on the 0.1 ms step clock, within one step of travel_s
  double settling_s = -1;   // simulated (b)..(f), (2), >= 0; < 0: never completed
  double positioning_s = -1;// travel + settling, (4)
  double max_tracking_error_deg = 0;
  double overshoot_deg = 0; // past the target in the direction of travel
  double in_window_s = -1;  // from (b) until in the tolerance window for good; < 0: not in it at the end
  bool completed = false;
};

// The figures a run's trace gives and their verdict, alike for one move
// (Evaluation) and a cycle (CycleEvaluation): computed by the same code
// (run_parts.hpp), written by the same code (output.hpp).
struct TraceFigures {
  double peak_torque_Nm = 0;       // max |motor torque| over all moves (trace samples)
  double rms_torque_Nm = 0;        // over the last simulated cycle / repetition (long dwells included, A-SIZE-9)
  double torque_capability_Nm = 0; // MotorModel::peak_torque_Nm
  double min_torque_headroom = 1;  // min over samples of 1 - |torque| / instantaneous capability
  double max_tracking_error_deg = 0;
  double tracking_limit_deg = 0;   // index 87.1
  double mean_loss_W = 0;          // copper + speed loss over the last cycle
  double steady_temperature_C = 0; // lumped model, continuous cycling
  std::optional<double> time_to_warning_s; // to 70 degC (115.1) from ambient; none if never
  std::optional<double> time_to_trip_s;    // to 75 degC (114.3, manual 7.2) from ambient; none if never
  bool feasible = false;
  std::string reason;              // why not feasible ("" when feasible)
  // The limit that failed (infeasible) or is closest to failing (feasible):
  // switch_on, settling, torque_at_speed, tracking, temperature, voltage,
  // max_positioning, max_cycle (A-SIZE-5).
  std::string binding_limit;
  Utilisation utilisation;
  double continuous_torque_Nm = 0; // A-SIZE-14
  SupplyFigures supply;
};

struct Evaluation : TraceFigures {
  ParameterSetValues set;
  double load_gcm2 = 0;            // actual load as MuJoCo computes it
  double travel_s = 0;             // Profile::rest_to_rest duration for the set's limits
  bool completed = false;          // every move reached Done; else the times below are not meaningful
  double settling_s = 0;           // worst move
  double positioning_s = 0;        // worst move
  double cycle_s = 0;              // 2 positionings + 2 handshakes + 2 dwells
  double handshake_s = 0;          // per move (A-SIZE-16)
  double cycles_per_min = 0;
  std::vector<MoveResult> moves;
  std::vector<TraceRow> trace;     // with SizingRequest::keep_trace
  double sim_time_s = 0;
};

struct SizingResult {
  bool recommended = false;  // searched (no explicit setting)
  Evaluation evaluation;     // the given set, or the recommendation (or the last one tried)
  int simulations = 0;       // twin runs made
  std::vector<Evaluation> tried; // every evaluation of the search, in order (without traces)
  // Search outcome (issue 17, A-SIZE-10): "fastest" without a target,
  // "gentlest" with --max-positioning-ms / --max-cycle-ms; "" for a given set.
  std::string objective;
  bool feasible = false;           // the answer holds (the target is met with all margins)
  std::string binding_limit;       // what stops a faster set ("module_limits": speed, acceleration and jerk at their maximum)
  double best_positioning_s = -1;  // fastest reachable (with a target that cannot be met)
  double best_cycle_s = -1;
  int candidates = 0;              // grid points the planner looked at
};

// Limits of the sizing itself (A-SIZE-1). What the module allows (load,
// speed, voltage window, settling parameters) is read from the parameter
// table's rows (manual 6.2), never retyped: max_load_gcm2() (twin), and
// the functions below.
inline constexpr double kMaxAngle_deg = 3600.0;
inline constexpr double kMaxDwell_s = 60.0;
// Index 85.1 / 85.2: the lowest and highest motor voltage the window can be
// configured to (A-SIZE-2).
double min_voltage_V();
double max_voltage_V();
// The world a sizing accepts (A-SCN-32): the supply within the index 85
// window (A-SIZE-2), the ambient 0 .. 50 degC (A-SIZE-1); the rest as any world.
WorldRanges sizing_world_ranges();
// Index 64+n.1: the highest speed a set can ask for, deg/s.
double max_speed_dps();
inline constexpr double kTemperatureWarning_C = 70.0; // manual 7.3 115.1

inline constexpr double kMaxThermalMargin_K = 45.0;
// Margins for "feasible" (A-SIZE-5).
inline constexpr double kTorqueMargin = 0.90;   // peak <= 90 % of capability
inline constexpr double kTrackingMargin = 0.80; // max tracking error <= 80 % of index 87.1

// `--model FILE` (issue 25): the model card with the file's overrides; ""
// the card as it is. Throws SizingInputError naming the option, file and line.
ModuleModel module_from_option(const std::string& model_path);

// Checks the request against the module's limits; throws SizingInputError
// with a message naming the option. Builds the load once to learn its
// inertia (MJCF loads); returns it in g cm^2.
double validate(const SizingRequest& request);

// Highest speed the motor reaches at this voltage (manual 3.5.3): the speed
// row's maximum (64+n.1) x U / 24, at most that maximum.
double voltage_speed_limit_dps(double voltage_V);

// The parameter set for a setting: raw values as written, read back as the
// device reads them; the writes for index 64 + request.parameter_set.
ParameterSetValues make_parameter_set(const SizingRequest& request, const MotionSetting& setting,
                                      double load_gcm2);

// Runs the twin for one parameter set (no validation).
Evaluation evaluate(const SizingRequest& request, const ParameterSetValues& set, bool keep_trace);

// How a search judges one parameter set: empty, evaluate() on the
// request's model; size --uncertainty (A-SIZE-UNC-3) judges it on the
// nominal and every sampled model (infeasible: the failing model's evaluation).
// The request is the search's (the fastest search judges without the targets).
using SetJudge = std::function<Evaluation(const SizingRequest&, const ParameterSetValues&)>;

// validate + evaluate the given set, or search the fastest feasible one, or
// (with a target) the gentlest one meeting it; a search judges its sets
// with `judge` when given.
SizingResult size(const SizingRequest& request, const SetJudge& judge = {});

// The searches behind size() (search.cpp, A-SIZE-10); load from validate().
SizingResult search_fastest(const SizingRequest& request, double load_gcm2, const SetJudge& judge = {});
SizingResult search_gentlest(const SizingRequest& request, double load_gcm2, const SetJudge& judge = {});
// The slowest point of the searches' grid (every limit at its lowest
// level): every grid point is at least as fast in all three limits.
MotionSetting slowest_setting(const SizingRequest& request);

// Torque the module holds continuously at this ambient without reaching the
// 70 degC warning minus the margin (A-SIZE-14), N m.
double continuous_torque_Nm(double ambient_C, double thermal_margin_K, const ModuleModel& module);

} // namespace sreh::sizing
