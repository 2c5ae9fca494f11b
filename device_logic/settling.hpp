// Settling per manual 3.5.2 (Fig. 3), 3.5.7 and 3.5.8, evaluated on the
// encoder reading: the tolerance window (half width), the waiting time whose
// clock restarts when the window is left, and the settling timeout counted
// from the end of the target trajectory (point b) to completion (point f).
#pragma once

namespace sreh {

struct SettlingParameters {
  double tolerance_rad = 0;   // index 64..71 sub 5 (half width)
  double wait_s = 0;          // sub 6
  double timeout_s = 0;       // sub 7
  bool timeout_enabled = true; // sub 8
};

enum class SettlingResult { Settling, Done, Timeout };

class SettlingMonitor {
 public:
  // Call at point (b): the target trajectory is complete.
  void start(const SettlingParameters& p);
  // One control step; `error_rad` = target - actual.
  SettlingResult update(double error_rad, double dt_s);
  double settling_time_s() const { return elapsed_; } // since point (b)

 private:
  SettlingParameters p_{};
  double elapsed_ = 0;   // since (b)
  double in_window_ = 0; // the clock of (c)..(f)
  bool inside_ = false;
};

} // namespace sreh
