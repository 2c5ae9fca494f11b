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
  Done,       // T5: positioning completed (f) (also after a Stop: the module is Done where it stopped)
  Error,      // an error ended it (114.x; error_code tells which bits), SettlingTimeout 114.8 included
  MotorOff,   // the motor was switched off or the power lost during the move
};

struct MoveRecord {
  uint32_t number = 0;        // 1 = first Move since power-on (T3 count)
  int parameter_set = 0;      // the set latched at (a), manual 3.2 T3
  int64_t start_ns = 0;       // (a) on the device clock (ns since its power-on)
  double start_s = 0;         // (a) on the run's clock (the twin shifts start_ns by the power-on instant)
  double start_deg = 0;       // where the setpoint stood at (a), process-data degrees
  double target_deg = 0;      // the commanded target (after relative / shortest-path resolution)
  double end_deg = 0;         // the encoder reading when the move ended
  // The latched set's settling parameters (64+n.5..8) that judged this move.
  double tolerance_deg = 0;
  double wait_ms = 0;
  double settling_timeout_ms = 0;
  bool settling_timeout_active = true;
  bool stopped = false;       // T4: Stop ended the travel early (braking profile)
  double travel_s = 0;        // (1) (a)..(b); for a stopped move until the braking profile ended
  std::optional<double> settling_s;    // (2) (b)..(f), >= 0; none unless Done
  std::optional<double> positioning_s; // (4) = travel + settling; none unless Done
  // (b).. the encoder entered the window for good, while the target is held
  // (servo.md); none while it is outside (e.g. after 115.3, manual 3.5.7).
  std::optional<double> in_window_s;
  double max_tracking_error_deg = 0;   // max |setpoint - encoder| over every control step of the move
  // Furthest past the commanded target in the direction of travel, from (a)
  // until the next move (>= 0; 0 for a zero-length move).
  double overshoot_deg = 0;
  MoveOutcome outcome = MoveOutcome::InProgress;
  uint8_t error_code = 0;     // the error byte when outcome == Error (manual 2.4)
  bool completed() const { return outcome == MoveOutcome::Done; }
  bool operator==(const MoveRecord&) const = default;
};

const char* outcome_name(MoveOutcome o);

// Builds MoveRecords from what the device knows each control step. Pure: the
// caller hands in time (integer ns since power-on) and readings. A record is
// open from (a) until the move ends, then held (overshoot and the window
// still watched while the module holds the target) until the next move or
// until the hold ends, then handed out by take_finished().
class MoveRecorder {
 public:
  struct Start {
    int64_t now_ns = 0;
    int parameter_set = 0;
    double start_deg = 0, target_deg = 0;
    double tolerance_deg = 0, wait_ms = 0, settling_timeout_ms = 0;
    bool settling_timeout_active = true;
  };
  void start(const Start& s);                     // (a): T3 accepted
  void mark_stopped();                            // T4 during the open move
  // Every control step while the record is open or held: the step's
  // tracking error |setpoint - encoder|, the encoder reading (process-data
  // degrees), and whether the target or braking trajectory still runs
  // (false from point (b) on).
  void step(int64_t now_ns, double tracking_error_deg, double position_deg, bool travelling);
  // The move ended: Done at (f), or Error / MotorOff. The record is held.
  void finish(int64_t now_ns, MoveOutcome outcome, double position_deg, uint8_t error_code = 0);
  void release();                                 // the hold ended (motor off, error, power off)

  bool open() const { return open_; }             // between (a) and its end
  bool holding() const { return held_; }          // ended, target still held
  // The open or held record, if any (for a snapshot at the end of a run).
  std::optional<MoveRecord> pending() const;
  // Records released since the last call, oldest first (the device keeps no history).
  std::vector<MoveRecord> take_finished();
  void restart_numbering() { count_ = 0; }        // power-on: numbers count from 1 again
  bool operator==(const MoveRecorder&) const = default;

 private:
  MoveRecord current_{};
  std::vector<MoveRecord> finished_;
  int64_t travel_end_ns_ = -1;
  double direction_ = 0; // sign(target - start)
  uint32_t count_ = 0;
  bool open_ = false;
  bool held_ = false;
  bool inside_ = false;
};

} // namespace sreh
