// Pieces shared by the single-move evaluation (evaluate.cpp) and the
// multi-segment cycle (cycle_evaluate.cpp): driving the twin as a PLC does,
// naming errors, supply figures from the trace, and judging the limits with
// their margins (A-SIZE-5), so that `feasible` means the same in both.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "device_logic/motor_model.hpp"
#include "device_logic/parameter_ids.hpp"
#include "sizing/sizing.hpp"

namespace sreh::sizing {

// A-SIZE-3: how long a move may take beyond travel + settling timeout
// before the run gives up on it (a stuck move always ends in an error first).
inline constexpr double kMoveSlack_s = 0.5;
inline constexpr int kSwitchOnCycles = 100; // T1 takes one IO-Link cycle; generous
// A-SIZE-9: a dwell longer than this is simulated only this long; the rest
// is accounted for with the loss and torque of the simulated hold.
inline constexpr double kMaxSimulatedDwell_s = 0.2;

std::string error_text(uint8_t code);    // "error 0x10: position tracking error (114.5)"
std::string warning_text(uint8_t code);
std::string category_of_error(uint8_t code); // the limit an error code points at (manual 7.2)
void write_all(Twin& twin, const std::vector<IsduWrite>& writes); // throws std::logic_error if refused
double read_display(Twin& twin, ParamId id);
int cycles_for(double seconds, double cycle_s);

// The twin a sizing run drives: the request's world (SizingRequest and
// CycleRequest alike), trace recorded.
inline TwinConfig sizing_twin_config(const WorldSpec& world) {
  TwinConfig cfg = twin_config(world);
  cfg.record_trace = true;
  cfg.visual_detail = false; // never rendered: coarse textures, faster builds (issue 31)
  return cfg;
}

template <class Pred>
bool run_until(Twin& twin, Pred done, int max_cycles) {
  for (int i = 0; i < max_cycles; ++i) {
    twin.run_cycle();
    if (done()) return true;
  }
  return false;
}

// A-SIZE-15: bus power of one sample and the supply figures of rows
// [from, end); RMS over [cycle_from, end).
double bus_power_W(const MotorModel& motor, const TraceRow& row);
SupplyFigures supply_figures(const MotorModel& motor, const std::vector<TraceRow>& rows, std::size_t from,
                             std::size_t cycle_from, double dt_s, double bus_max_V);

// Failed checks, each with the limit it names (A-SIZE-5).
struct Reasons {
  std::vector<std::pair<std::string, std::string>> list; // binding limit, text
  void add(std::string limit, std::string text) { list.emplace_back(std::move(limit), std::move(text)); }
};

// What the limit checks look at (A-SIZE-5).
struct LimitFigures {
  uint8_t warnings = 0;             // OR of the warning codes of the run
  double peak_torque_Nm = 0;
  double torque_capability_Nm = 0;
  double min_torque_headroom = 1;
  double worst_headroom_speed_dps = 0;
  double voltage_V = 24;
  double max_tracking_error_deg = 0;
  double tracking_limit_deg = 0;
  double steady_temperature_C = 0;
  double ambient_C = 25;
  double thermal_margin_K = 5;
  std::optional<double> time_to_warning_s;
  // Targets: value and bound, s (single move only).
  std::optional<std::pair<double, double>> positioning_target, cycle_target;
};

struct Judgement {
  bool feasible = false;
  std::string reason;         // the failed checks, "; "-joined
  std::string binding_limit;  // the first failure, or the limit closest to failing
};

// Adds the limit checks to `reasons` (run failures first, when the run
// already failed the limits are not judged) and names the binding limit.
Judgement judge(const LimitFigures& f, Reasons reasons);

// What the torque scan finds besides the figures it sets.
struct TorqueScan {
  uint8_t warnings = 0;                // OR of the warning codes
  double worst_headroom_speed_dps = 0; // speed of the smallest headroom
};

// Peak torque and smallest headroom over rows [from, end), all moves of all
// cycles (A-SIZE-8), into `f`.
TorqueScan scan_torque(const std::vector<TraceRow>& rows, std::size_t from, TraceFigures& f);

// After the RMS torque and the mean loss are set: the supply figures (rows
// [from, end), RMS over [cycle_from, end)), the temperature, the continuous
// torque and the utilisation (A-SIZE-6, 14, 15).
void derive_figures(const ModuleModel& module, const std::vector<TraceRow>& rows, std::size_t from,
                    std::size_t cycle_from, double dt_s, double ambient_C, double thermal_margin_K, TraceFigures& f);

// The limit figures of a run (without targets).
LimitFigures limit_figures(const TraceFigures& f, const TorqueScan& scan, double voltage_V, double ambient_C,
                           double thermal_margin_K);

// Judges (judge()) and records the verdict in `f`.
void judge_into(const LimitFigures& limits, Reasons reasons, TraceFigures& f);

} // namespace sreh::sizing
