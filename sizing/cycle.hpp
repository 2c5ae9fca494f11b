// Multi-segment cycles (issue 17): `sreh-twin size --cycle FILE.yaml`.
// A cycle is a list of moves (absolute targets or relative distances, each
// with its parameter set), dwells and load changes (grip / release), with
// mounting, load, supply, ambient and process torque. It is evaluated by
// running it in the twin exactly as evaluate() runs a single move: the sets
// written over ISDU, Motor On, moves through process data; the cycle is
// repeated and the last repetition is the answer (A-SIZE-17..21).
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "sizing/sizing.hpp"

namespace sreh::sizing {

// One move: to `target_deg` (absolute), or by it (`relative: true`, manual 2.2).
struct CycleMove {
  double target_deg = 0;
  bool relative = false;
  std::optional<int> parameter_set;        // 0..7; unset: assigned (A-SIZE-18)
  std::optional<double> speed_dps, accel_pct, jerk_pct; // given values; none given: recommended
  std::optional<double> process_torque_Nm; // >= 0, opposing the motion; unset: the cycle's
};
// A pause after Done; an optional holding torque (signed, positive = the
// positive direction of the position values, factory index 82). A process
// torque acts from its segment's start until the next move or dwell sets
// its own (A-SIZE-21).
struct CycleDwell {
  double dwell_s = 0;
  double process_torque_Nm = 0;
};
// Another load from now on (a gripper picks or releases a part).
struct CycleLoadChange {
  LoadSpec load = NoLoad{};
};

struct CycleSegment {
  std::variant<CycleMove, CycleDwell, CycleLoadChange> what;
  int line = 0, column = 0; // in the cycle file
};

struct CycleRequest {
  std::string file;               // for messages
  // The world: `model`, `device` (or `supply` and `ambient_C`), `load` (at
  // the start of every repetition, A-SIZE-19), `mounting`, `world`, read
  // as in a scenario (A-SCN-32); `--model FILE` sets `world.model_file` too.
  WorldSetup world;
  SettlingSpec settling;          // of every set
  double process_torque_Nm = 0;   // on every move without its own
  double thermal_margin_K = 5.0;
  int handshake_cycles = 4;       // A-SIZE-16
  int cycles = 3;                 // repetitions simulated (A-SIZE-17)
  std::vector<CycleSegment> segments;
  bool keep_trace = false;        // for the report
  // Called as each simulation starts, the searches' included (the studio's
  // progress bar, the CLI's progress line); from several threads at once
  // with --uncertainty. Empty: nothing.
  std::function<void()> on_simulation;
  // Threads for the searches of the recommended sets (one set's search per
  // thread, issue 37); the answer does not depend on it.
  int threads = 1;
};

// What one listed segment did in the last repetition.
struct SegmentResult {
  std::string kind;              // "move", "dwell", "load"
  double duration_s = 0;         // move: positioning + handshake; dwell: dwell_s; load: 0
  // Moves:
  int parameter_set = -1;
  double start_deg = 0, target_deg = 0; // absolute, process-data degrees
  double load_gcm2 = 0;          // actual load on the flange during the move (MuJoCo; the set's 64+n.4 says the same)
  double process_torque_Nm = 0;
  double travel_s = 0;           // planned (manual 3.5.2 (1))
  double settling_s = -1;        // simulated; < 0: never completed
  double positioning_s = -1;
  double peak_torque_Nm = 0;     // from Move until Done
  double rms_torque_Nm = 0;
  double max_tracking_error_deg = 0;
  bool completed = false;
  // Dwells: the holding torque's RMS; load changes: the new load.
  double hold_rms_torque_Nm = 0;
  // Trace rows of the segment in the last repetition (reports): [row_from, row_to).
  std::size_t row_from = 0, row_to = 0;
};

struct CycleEvaluation : TraceFigures {
  std::vector<ParameterSetValues> sets; // every set used, in set order
  std::vector<SegmentResult> segments;  // one per listed segment
  bool completed = false;         // every move of every repetition reached Done
  double cycle_s = 0;             // sum of the segments' durations (handshake per move included)
  double handshake_s = 0;         // per move
  double cycles_per_min = 0;
  std::vector<TraceRow> trace;    // with keep_trace
  std::size_t last_repetition_row = 0; // first trace row of the last repetition
  double sim_time_s = 0;
};

struct CycleResult {
  CycleEvaluation evaluation;
  std::vector<MotionSetting> settings; // per plan set, as evaluated last (given, recommended, slowed down)
  bool recommended = false;       // at least one set was searched
  int simulations = 0;            // twin runs, searches included
  int backoffs = 0;               // A-SIZE-20: times the recommended sets were slowed down
};

// Reads a cycle file through the YAML safety layer; loads and mounting with
// the scenario parser. Throws SizingInputError "FILE:LINE:COL: ..." (exit 2).
CycleRequest parse_cycle_file(const std::string& path);
CycleRequest parse_cycle_text(const std::string& text, const std::string& file, const std::string& base_dir);

// The parameter set of every move (A-SIZE-18): numbers and given values.
// Throws SizingInputError for conflicts (a set used with two loads, two
// different values, more than 8 sets).
struct SetPlan {
  int set = 1;
  double load_gcm2 = 0;              // the actual inertia of the load during its moves
  std::optional<MotionSetting> given;
  double longest_move_deg = 0;       // for the recommendation
  LoadSpec load = NoLoad{};
};
struct CyclePlan {
  std::vector<SetPlan> sets;
  std::vector<int> move_set;         // per segment: index into sets, -1 for non-moves
};
CyclePlan plan_sets(const CycleRequest& request);

// Runs the cycle with the sets (each set's setting filled in).
CycleEvaluation evaluate_cycle(const CycleRequest& request, const CyclePlan& plan,
                               const std::vector<MotionSetting>& settings, bool keep_trace);

// validate + plan + recommend what is not given (A-SIZE-20) + evaluate.
CycleResult size_cycle(const CycleRequest& request);

} // namespace sreh::sizing
