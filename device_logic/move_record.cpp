#include "device_logic/move_record.hpp"

#include <algorithm>
#include <cmath>

namespace sreh {

const char* outcome_name(MoveOutcome o) {
  switch (o) {
    case MoveOutcome::InProgress: return "in_progress";
    case MoveOutcome::Done: return "done";
    case MoveOutcome::Stopped: return "stopped";
    case MoveOutcome::Error: return "error";
    case MoveOutcome::MotorOff: return "motor_off";
  }
  return "?";
}

void MoveRecorder::start(const Start& s) {
  if (open_) finish(s.now_ns, MoveOutcome::Stopped, current_.end_deg);
  current_ = MoveRecord{};
  current_.number = ++count_;
  current_.parameter_set = s.parameter_set;
  current_.start_s = seconds(s.now_ns);
  current_.start_deg = s.start_deg;
  current_.target_deg = s.target_deg;
  current_.end_deg = s.start_deg;
  current_.tolerance_deg = s.tolerance_deg;
  current_.wait_ms = s.wait_ms;
  current_.settling_timeout_ms = s.settling_timeout_ms;
  current_.settling_timeout_active = s.settling_timeout_active;
  start_ns_ = s.now_ns;
  travel_end_ns_ = -1;
  window_entry_ns_ = -1;
  const double distance = s.target_deg - s.start_deg;
  direction_ = distance > 0 ? 1.0 : (distance < 0 ? -1.0 : 0.0);
  open_ = true;
}

void MoveRecorder::step(int64_t now_ns, double setpoint_deg, double position_deg, bool travelling) {
  if (!open_) return;
  current_.max_tracking_error_deg = std::max(current_.max_tracking_error_deg, std::abs(setpoint_deg - position_deg));
  current_.overshoot_deg = std::max(current_.overshoot_deg, (position_deg - current_.target_deg) * direction_);
  current_.end_deg = position_deg;
  if (!travelling && travel_end_ns_ < 0) { // point (b)
    travel_end_ns_ = now_ns;
    current_.travel_s = seconds(now_ns - start_ns_);
  }
}

void MoveRecorder::entered_window(int64_t now_ns) {
  if (open_) window_entry_ns_ = now_ns;
}

void MoveRecorder::finish(int64_t now_ns, MoveOutcome outcome, double position_deg, uint8_t error_code) {
  if (!open_) return;
  current_.end_deg = position_deg;
  current_.outcome = outcome;
  current_.error_code = outcome == MoveOutcome::Error ? error_code : 0;
  if (travel_end_ns_ < 0) current_.travel_s = seconds(now_ns - start_ns_); // ended during travel
  if (outcome == MoveOutcome::Done && travel_end_ns_ >= 0) {
    // Fig. 3: settling from (b) to (f), never negative; positioning = travel + settling.
    current_.settling_s = seconds(now_ns - travel_end_ns_);
    current_.positioning_s = seconds(now_ns - start_ns_);
    current_.in_window_s = seconds(std::max(window_entry_ns_, travel_end_ns_) - travel_end_ns_);
  }
  finished_.push_back(current_);
  open_ = false;
}

std::vector<MoveRecord> MoveRecorder::take_finished() {
  std::vector<MoveRecord> out;
  out.swap(finished_);
  return out;
}

} // namespace sreh
