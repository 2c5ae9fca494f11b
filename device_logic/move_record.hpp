// One move as the device saw it (issue 13: move records come from the
// device, which latched the parameter set), in manual 3.5.2 terms (Fig. 3):
// (a) Move accepted, (b) the target trajectory ends, (f) positioning
// completed. Every consumer (runner, report, sizing, JSON, Python, serve)
// uses this one record.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

namespace sreh {

enum class MoveOutcome : uint8_t {
  InProgress, // not ended yet
  Done,       // T5: positioning completed (f)
  Stopped,    // T4: stopped before the target (Stop during the move)
  Error,      // an error ended it (114.x; error_code tells which bit)
  MotorOff,   // the motor was switched off / power lost during the move
};

struct MoveRecord {
  uint32_t number = 0;        // 1 = first Move since power-on (T3 count)
  int parameter_set = 0;      // the set latched at (a), manual 3.2 T3
  double start_s = 0;         // (a), device time since power-on of the run
  double start_deg = 0;       // where the setpoint stood at (a), process-data degrees
  double target_deg = 0;      // the commanded target (after relative / shortest-path resolution)
  double end_deg = 0;         // the encoder reading when the move ended
  // The latched set's settling parameters (64+n.5..8) that judged this move.
  double tolerance_deg = 0;
  double wait_ms = 0;
  double settling_timeout_ms = 0;
  bool settling_timeout_active = true;
  double travel_s = 0;        // (1) (a)..(b); for a stopped move: until the braking profile ended
  std::optional<double> settling_s;    // (2) (b)..(f); none unless Done
  std::optional<double> positioning_s; // (4) travel + settling; none unless Done
  std::optional<double> in_window_s;   // (b).. the flange entered the window for good; none unless Done
  double max_tracking_error_deg = 0;   // max |setpoint - encoder| over every control step of the move
  double overshoot_deg = 0;   // max distance past the target in the direction of travel (0 for a zero-length move)
  MoveOutcome outcome = MoveOutcome::InProgress;
  uint8_t error_code = 0;     // the error byte when outcome == Error (manual 2.4)
  bool completed() const { return outcome == MoveOutcome::Done; }
};

const char* outcome_name(MoveOutcome o);

// Builds MoveRecords from what the device knows each control step. Pure: the
// caller hands in time (integer ns since power-on) and readings.
class MoveRecorder {
 public:
  struct Start {
    int64_t now_ns = 0;
    int parameter_set = 0;
    double start_deg = 0, target_deg = 0;
    double tolerance_deg = 0, wait_ms = 0, settling_timeout_ms = 0;
    bool settling_timeout_active = true;
  };
  // (a): T3 accepted. An open record (should not happen) is ended as Stopped.
  void start(const Start& s);
  // Every control step while a record is open. `travelling`: the target or
  // braking trajectory still runs (false from point (b) on).
  void step(int64_t now_ns, double setpoint_deg, double position_deg, bool travelling);
  // The move ended: Done at (f), or Stopped / Error / MotorOff.
  void finish(int64_t now_ns, MoveOutcome outcome, double position_deg, uint8_t error_code = 0);
  // (c)/(e): the flange entered the window and has stayed in it since (reported at Done).
  void entered_window(int64_t now_ns);

  bool open() const { return open_; }
  const MoveRecord& current() const { return current_; }
  // Records ended since the last call, oldest first (the device keeps no history).
  std::vector<MoveRecord> take_finished();

 private:
  static double seconds(int64_t ns) { return static_cast<double>(ns) / 1e9; } // exact for whole ms, no float noise
  MoveRecord current_{};
  std::vector<MoveRecord> finished_;
  int64_t start_ns_ = 0;
  int64_t travel_end_ns_ = -1;
  int64_t window_entry_ns_ = -1;
  double direction_ = 0; // sign(target - start)
  uint32_t count_ = 0;
  bool open_ = false;
};

} // namespace sreh
