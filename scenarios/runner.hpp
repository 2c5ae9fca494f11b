// Runs a Scenario on a Twin: steps on IO-Link cycle boundaries, the device
// reached only through process data and ISDU (architecture.md). Every check
// is recorded; a failed check does not stop the run unless the scenario says
// `stop_on_failure: true`. A wait_until that is not met gives up after its
// `within_s`, so no run can hang.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "scenarios/limits.hpp"
#include "scenarios/scenario.hpp"
#include "twin/twin.hpp"

namespace sreh {

struct CheckRecord {
  std::string step;        // "4", "5.2"; "device.isdu[0]" or "expect" outside the steps
  int line = 0;            // scenario line (1-based)
  std::string description; // "wait_until state Done within 1 s"
  bool passed = false;
  double t_s = 0;          // simulated time when it was decided
  std::string actual;      // what was observed
};

struct FinalState {
  State state = State::MotorOff;
  double position_deg = 0;
  uint8_t error_code = 0;
  uint8_t warning_code = 0;
  LedColor led = LedColor::Off;
};

struct RunResult {
  std::string name;
  bool passed = true;
  bool stopped_early = false;        // stop_on_failure ended the run
  std::vector<std::string> failures; // "step 4 (line 12): ..."
  // Commissioning hints (issue 28, A-SCN-30): "hint: parameter set N is
  // configured for C g cm^2, ...". The twin's knowledge, not the device's.
  std::vector<std::string> hints;
  std::vector<CheckRecord> checks;
  std::vector<MoveRecord> moves;
  // Counted whether kept above or streamed (RunOptions sinks).
  uint64_t checks_recorded = 0;
  uint64_t checks_held = 0;
  uint64_t moves_recorded = 0;
  FinalState final_state;
  double sim_time_s = 0;
  uint64_t cycles = 0;
  double max_tracking_error_deg = 0;  // every control step (Twin::max_tracking_error_deg)
  double max_temperature_C = 0;
  double min_supply_V = 0;
  double max_supply_V = 0;
  std::vector<TraceRow> trace;        // with RunOptions::record_trace
  std::vector<uint8_t> nvm_image;     // non-volatile memory at the end (--save-nvm)
  // The index-87 tracking limit at the end of the run, for plots (0 when
  // monitoring is off). Each move's tolerance and waiting time are in its record.
  double tracking_limit_deg = 0;
};

struct RunOptions {
  bool record_trace = false;   // keep the trace in memory: RunResult::trace
  // Stream the trace instead, row by row as the cycles run (memory flat with
  // run length, issue 12); RunResult::trace stays empty.
  std::function<void(const TraceRow&)> trace_sink;
  // Stream the records that grow with run length instead of keeping them
  // (issue 12): each is handed over once, in run order, as soon as it is
  // final, and the matching RunResult vector stays empty.
  std::function<void(const CheckRecord&)> check_sink;
  std::function<void(const std::string&)> failure_sink;
  std::function<void(const MoveRecord&)> move_sink;
  Limits limits;               // checked before the run starts (check_run_bound)
  // Called after every IO-Link cycle (video frames, progress).
  std::function<void(const Twin&)> on_cycle;
  // Called when a step begins (the video overlay names it).
  std::function<void(const Step&)> on_step;
  // Called with every answer to a scenario's isdu_read step (the master log
  // records the temperature the PLC polled, issue 26).
  std::function<void(uint16_t index, uint8_t subindex, const IsduResult& result)> on_isdu_read;
};

// The twin a scenario describes (load, world, supply, thermal, clocks, NVM).
// Throws ScenarioError if the NVM image file cannot be read.
TwinConfig make_twin_config(const Scenario& scenario);

// Throws ScenarioError for input the twin rejects (e.g. an invalid MJCF
// load), citing the scenario line, and for a scenario that could exceed
// options.limits (before running).
RunResult run_scenario(const Scenario& scenario, const RunOptions& options = {});

// Everything run_scenario refuses before the first cycle (the run bound, the
// NVM image file, a setup the twin rejects), without running: throws
// ScenarioError as run_scenario would. For checking a batch before any runs.
void check_setup(const Scenario& scenario, const Limits& limits);

} // namespace sreh
