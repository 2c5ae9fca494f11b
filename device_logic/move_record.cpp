#include "device_logic/move_record.hpp"

#include <algorithm>
#include <cmath>

namespace sreh {
namespace {
// Integer nanoseconds to seconds in one division: 0.3625 stays 0.3625 (no
// accumulated float noise in JSON or CSV).
double seconds(int64_t ns) { return static_cast<double>(ns) / 1e9; }
} // namespace

const char* outcome_name(MoveOutcome o) {
  switch (o) {
    case MoveOutcome::InProgress: return "in_progress";
    case MoveOutcome::Done: return "done";
    case MoveOutcome::Error: return "error";
    case MoveOutcome::MotorOff: return "motor_off";
  }
  return "?";
}

void MoveRecorder::start(const Start& s) {
  if (open_) finish(s.now_ns, MoveOutcome::MotorOff, current_.end_deg); // cannot happen: T3 needs Ready/Done
  release();
  current_ = MoveRecord{};
  current_.number = ++count_;
  current_.parameter_set = s.parameter_set;
  current_.start_ns = s.now_ns;
  current_.start_s = seconds(s.now_ns);
  current_.start_deg = s.start_deg;
  current_.target_deg = s.target_deg;
  current_.end_deg = s.start_deg;
  current_.tolerance_deg = s.tolerance_deg;
  current_.wait_ms = s.wait_ms;
  current_.settling_timeout_ms = s.settling_timeout_ms;
  current_.settling_timeout_active = s.settling_timeout_active;
  travel_end_ns_ = -1;
  inside_ = false;
  const double distance = s.target_deg - s.start_deg;
  direction_ = distance > 0 ? 1.0 : (distance < 0 ? -1.0 : 0.0);
  open_ = true;
}

void MoveRecorder::mark_stopped() {
  if (open_) current_.stopped = true;
}

void MoveRecorder::step(int64_t now_ns, double tracking_error_deg, double position_deg, bool travelling) {
  if (!open_ && !held_) return;
  current_.overshoot_deg = std::max(current_.overshoot_deg, (position_deg - current_.target_deg) * direction_);
  if (open_) {
    current_.max_tracking_error_deg = std::max(current_.max_tracking_error_deg, tracking_error_deg);
    current_.end_deg = position_deg;
    if (!travelling && travel_end_ns_ < 0) { // point (b)
      travel_end_ns_ = now_ns;
      current_.travel_s = seconds(now_ns - current_.start_ns);
    }
  }
  if (travel_end_ns_ >= 0) { // the window, inclusive (A-MOTION-6), from (b) while the target is held
    const bool inside = std::abs(position_deg - current_.target_deg) <= current_.tolerance_deg;
    if (inside && !inside_) current_.in_window_s = seconds(now_ns - travel_end_ns_);
    if (!inside) current_.in_window_s.reset();
    inside_ = inside;
  }
}

void MoveRecorder::finish(int64_t now_ns, MoveOutcome outcome, double position_deg, uint8_t error_code) {
  if (!open_) return;
  current_.end_deg = position_deg;
  current_.outcome = outcome;
  current_.error_code = outcome == MoveOutcome::Error ? error_code : 0;
  if (travel_end_ns_ < 0) current_.travel_s = seconds(now_ns - current_.start_ns); // ended during travel
  if (outcome == MoveOutcome::Done && travel_end_ns_ >= 0) {
    // Fig. 3: settling from (b) to (f), never negative; positioning = travel + settling.
    current_.settling_s = seconds(now_ns - travel_end_ns_);
    current_.positioning_s = seconds(now_ns - current_.start_ns);
  } else {
    current_.in_window_s.reset();
  }
  open_ = false;
  held_ = outcome == MoveOutcome::Done;
  if (!held_) finished_.push_back(current_);
}

void MoveRecorder::release() {
  if (open_) return;
  if (held_) finished_.push_back(current_);
  held_ = false;
}

std::optional<MoveRecord> MoveRecorder::pending() const {
  if (!open_ && !held_) return std::nullopt;
  return current_;
}

std::vector<MoveRecord> MoveRecorder::take_finished() {
  std::vector<MoveRecord> out;
  out.swap(finished_);
  return out;
}

} // namespace sreh
