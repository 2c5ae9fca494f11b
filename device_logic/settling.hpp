// Settling per manual 3.5.2 (Fig. 3), 3.5.7 and 3.5.8, evaluated on the
// encoder reading: the tolerance window (half width), the waiting time whose
// clock restarts when the window is left, and the settling timeout counted
// from the end of the target trajectory (point b) to completion (point f).
// Decisions (docs/assumptions/motion.md A-MOTION-6..9): the window is
// inclusive (|error| <= tolerance); the clock is an integer nanosecond count
// (no float drift); a wait time of 0 completes on the first in-window
// sample; completion and timeout at the same instant count as completion.
#pragma once
#include <cstdint>

namespace sreh {

struct SettlingParameters {
  double tolerance_rad = 0;   // index 64..71 sub 5 (half width)
  double wait_s = 0;          // sub 6
  double timeout_s = 0;       // sub 7
  bool timeout_enabled = true; // sub 8
  bool operator==(const SettlingParameters&) const = default;
};

enum class SettlingResult { Settling, Done, Timeout };

class SettlingMonitor {
 public:
  // Call at point (b): the target trajectory is complete.
  void start(const SettlingParameters& p);
  // One control step; `error_rad` = target - actual, sampled `dt_s` after
  // the previous update (or after start()). dt_s = 0 evaluates a sample at
  // point (b) itself. Done and Timeout are sticky until the next start().
  SettlingResult update(double error_rad, double dt_s);
  SettlingResult update_ns(double error_rad, int64_t dt_ns); // the same, integer time
  double settling_time_s() const { return static_cast<double>(elapsed_ns_) * 1e-9; } // since point (b)
  double in_window_time_s() const { return static_cast<double>(in_window_ns_) * 1e-9; } // since (c)/(e)
  SettlingResult result() const { return result_; }

  // The tolerance window test, inclusive (manual 3.5.2 (5): "maximum
  // permissible deviation"). The device reuses it for warning 115.3.
  static bool within(double error_rad, double tolerance_rad);

  bool operator==(const SettlingMonitor&) const = default;

 private:
  SettlingParameters p_{};
  int64_t wait_ns_ = 0;
  int64_t timeout_ns_ = 0;
  int64_t elapsed_ns_ = 0;   // since (b)
  int64_t in_window_ns_ = 0; // the clock of (c)..(f)
  bool inside_ = false;
  SettlingResult result_ = SettlingResult::Settling;
};

} // namespace sreh
