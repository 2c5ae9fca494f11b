// The Device's monitors as values (device_monitors.hpp): each one's step
// function alone, with the timing the manual and ASSUMPTIONS.md give.
// The Device answering them is in monitored_faults_test.cpp.
#include <gtest/gtest.h>

#include "device_logic/device_monitors.hpp"
#include "device_logic/faults.hpp"

namespace sreh {
namespace {

constexpr int64_t kStep_ns = 100'000; // 0.1 ms control step

TEST(LinkWatchdogMonitor, ExpiresOnceAfterMax20msOr3Cycles_A_LINK_1) {
  LinkWatchdog w;
  EXPECT_EQ(w.timeout_ns(), 20'000'000); // 3 x 2 ms < 20 ms
  w.master_cycle_ns = 32'000'000;
  EXPECT_EQ(w.timeout_ns(), 96'000'000);
  w.master_cycle_ns = 2'000'000;
  w.feed();
  int lost_at = -1, losses = 0;
  for (int i = 1; i <= 400; ++i) {
    if (w.step(kStep_ns)) lost_at = i, ++losses;
  }
  EXPECT_EQ(lost_at, 201); // silence > 20 ms: the 201st step of 0.1 ms
  EXPECT_EQ(losses, 1);
  EXPECT_FALSE(w.link_up);
  w.feed();
  EXPECT_TRUE(w.link_up);
  EXPECT_FALSE(w.step(kStep_ns));
}

TEST(VoltageMonitorAlone, DebouncedOnOneSide_A_MON_1_7_2_114_4) {
  VoltageMonitor v;
  int first = -1;
  for (int i = 1; i <= 30 && first < 0; ++i) {
    if (v.step(17.0, 18.0, 30.0, kStep_ns) != 0) first = i;
  }
  EXPECT_EQ(first, 21); // the first sample outside starts the 2 ms clock
  EXPECT_EQ(v.step(17.0, 18.0, 30.0, kStep_ns), cause::kVoltageLow);
  EXPECT_EQ(v.step(24.0, 18.0, 30.0, kStep_ns), 0); // back inside: at once
  // Low then high restarts the debounce.
  for (int i = 0; i < 15; ++i) v.step(17.0, 18.0, 30.0, kStep_ns);
  for (int i = 0; i < 20; ++i) EXPECT_EQ(v.step(31.0, 18.0, 30.0, kStep_ns), 0) << i;
  EXPECT_EQ(v.step(31.0, 18.0, 30.0, kStep_ns), cause::kVoltageHigh);
}

TEST(TemperatureMonitorAlone, HysteresisWarningError_7_2_7_3_A_MON_2) {
  EXPECT_FALSE(TemperatureMonitor::step(69.9, false).warning);
  EXPECT_TRUE(TemperatureMonitor::step(70.0, false).warning);
  EXPECT_TRUE(TemperatureMonitor::step(69.5, true).warning);  // inside the 1 C band: kept
  EXPECT_FALSE(TemperatureMonitor::step(69.5, false).warning);
  EXPECT_FALSE(TemperatureMonitor::step(68.9, true).warning); // below 69 C: cleared
  EXPECT_FALSE(TemperatureMonitor::step(74.9, true).over_temperature);
  EXPECT_TRUE(TemperatureMonitor::step(75.0, true).over_temperature);
}

TEST(TrackingMonitorAlone, StepPeakAndLimit_6_2_87) {
  TrackingMonitor t;
  EXPECT_FALSE(t.step(0.5, 1.0, true));
  EXPECT_FALSE(t.step(1.0, 1.0, true)); // at the limit: not beyond
  EXPECT_TRUE(t.step(1.5, 1.0, true));
  EXPECT_FALSE(t.step(9.0, 1.0, false)); // monitoring off
  t.idle();
  EXPECT_EQ(t.step_error_deg, 0.0);
  EXPECT_EQ(t.take_peak(), 9.0);
  EXPECT_EQ(t.take_peak(), 0.0);
}

TEST(DiagnosticsClockAlone, WholeMinutesNoDrift_6_3) {
  DiagnosticsClock d;
  int64_t powered = 0, moving = 0;
  // 3 minutes of 0.1 ms steps, moving half of the time.
  for (int64_t i = 0; i < 3 * 600'000; ++i) {
    const auto m = d.step(kStep_ns, true, i % 2 == 0, false);
    powered += m.powered, moving += m.moving;
  }
  EXPECT_EQ(powered, 3);
  EXPECT_EQ(moving, 1);
  EXPECT_EQ(d.powered_rem_ns, 0);
  EXPECT_EQ(d.temp_warn_rem_ns, 0);
  EXPECT_EQ(d.step(5 * kMinute_ns + 1, false, false, true).temp_warning, 5); // a long step: all of them
}

TEST(LocatorAlone, StopsAfterTenMinutes_6_6) {
  Locator l;
  l.start(1000);
  l.step(1000 + kLocatorDuration_ns - 1);
  EXPECT_TRUE(l.active);
  l.step(1000 + kLocatorDuration_ns);
  EXPECT_FALSE(l.active);
  l.start(0);
  l.stop();
  EXPECT_FALSE(l.active);
}

} // namespace
} // namespace sreh
