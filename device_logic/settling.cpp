// Settling monitor, manual 3.5.2 Fig. 3 points (b)-(f), 3.5.7, 3.5.8.
#include "device_logic/settling.hpp"

#include <cmath>

#include "device_logic/units.hpp"

namespace sreh {
// Time as integer nanoseconds: 25 ms at 0.1 ms steps is exactly 250 steps,
// whatever the float rounding of the step sum would say.

bool SettlingMonitor::within(double error_rad, double tolerance_rad) {
  return std::abs(error_rad) <= tolerance_rad;
}

void SettlingMonitor::start(const SettlingParameters& p) { // point (b)
  p_ = p;
  wait_ns_ = seconds_to_ns(p.wait_s);
  timeout_ns_ = seconds_to_ns(p.timeout_s);
  elapsed_ns_ = 0;
  in_window_ns_ = 0;
  inside_ = false;
  result_ = SettlingResult::Settling;
}

SettlingResult SettlingMonitor::update(double error_rad, double dt_s) {
  return update_ns(error_rad, seconds_to_ns(dt_s));
}

SettlingResult SettlingMonitor::update_ns(double error_rad, int64_t dt_ns) {
  if (result_ != SettlingResult::Settling) return result_;
  elapsed_ns_ += dt_ns;
  if (within(error_rad, p_.tolerance_rad)) {
    if (inside_) {
      in_window_ns_ += dt_ns;
    } else { // (c) first entry, or (e) re-entry: the clock restarts from zero
      inside_ = true;
      in_window_ns_ = 0;
    }
    if (in_window_ns_ >= wait_ns_) return result_ = SettlingResult::Done; // (f)
  } else { // (d) left before the waiting time expired: the clock stops
    inside_ = false;
    in_window_ns_ = 0;
  }
  // Manual 3.5.8: the settling time (b)..(f) is limited, when enabled.
  if (p_.timeout_enabled && elapsed_ns_ >= timeout_ns_) return result_ = SettlingResult::Timeout;
  return result_;
}

} // namespace sreh
