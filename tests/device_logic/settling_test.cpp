// Settling monitor: manual 3.5.2 Fig. 3 points (a)-(f), 3.5.7, 3.5.8.
#include <gtest/gtest.h>

#include <cmath>

#include "device_logic/settling.hpp"

namespace sreh {
namespace {

constexpr double kDt = 1e-4; // control step

SettlingParameters params(double tol, double wait_s, double timeout_s, bool enabled = true) {
  return SettlingParameters{tol, wait_s, timeout_s, enabled};
}

// Feeds `n` samples of `error` and returns the last result.
SettlingResult feed(SettlingMonitor& m, double error, int n) {
  SettlingResult r = SettlingResult::Settling;
  for (int i = 0; i < n; ++i) r = m.update(error, kDt);
  return r;
}

TEST(Settling, Fig3PointsBtoF) {
  // manual 3.5.2 Fig. 3: (b) trajectory done, outside; (c) enters, clock runs;
  // (d) leaves before the wait time, clock stops; (e) re-enters, clock reset;
  // (f) wait time expired inside: complete.
  SettlingMonitor m;
  m.start(params(1.0, 0.0025, 0.1)); // (b): wait 25 steps
  EXPECT_EQ(feed(m, 3.0, 10), SettlingResult::Settling); // (b)..(c) outside
  EXPECT_EQ(feed(m, 0.5, 20), SettlingResult::Settling); // (c): clock runs 19 steps
  EXPECT_NEAR(m.in_window_time_s(), 19 * kDt, 1e-12);
  EXPECT_EQ(feed(m, -1.5, 3), SettlingResult::Settling); // (d): left, clock stopped
  EXPECT_EQ(m.in_window_time_s(), 0.0);
  EXPECT_EQ(feed(m, -0.2, 25), SettlingResult::Settling); // (e): clock restarted from 0
  EXPECT_EQ(m.update(0.1, kDt), SettlingResult::Done);    // (f): 25 steps inside
  EXPECT_NEAR(m.settling_time_s(), 59 * kDt, 1e-12);      // (b)..(f)
  // Sticky: leaving the window afterwards is the device's warning 115.3, not ours.
  EXPECT_EQ(m.update(5.0, kDt), SettlingResult::Done);
}

TEST(Settling, WindowIsInclusive) {
  // manual 3.5.2 (5): tolerance = maximum permissible deviation, so |e| == tol is inside.
  EXPECT_TRUE(SettlingMonitor::within(1e-3, 1e-3));
  EXPECT_TRUE(SettlingMonitor::within(-1e-3, 1e-3));
  EXPECT_FALSE(SettlingMonitor::within(std::nextafter(1e-3, 1.0), 1e-3));
  SettlingMonitor m;
  m.start(params(1e-3, 0.0, 0.1));
  EXPECT_EQ(m.update(-1e-3, kDt), SettlingResult::Done);
}

TEST(Settling, ZeroWaitCompletesOnFirstInWindowSample) {
  // manual 3.5.7 with waiting time 0: the first sample inside is (c) = (f).
  SettlingMonitor m;
  m.start(params(1.0, 0.0, 0.1));
  EXPECT_EQ(m.update(2.0, kDt), SettlingResult::Settling);
  EXPECT_EQ(m.update(0.0, kDt), SettlingResult::Done);
  // A sample at point (b) itself (dt = 0) already in the window: done at once.
  m.start(params(1.0, 0.0, 0.1));
  EXPECT_EQ(m.update(0.0, 0.0), SettlingResult::Done);
  EXPECT_EQ(m.settling_time_s(), 0.0);
}

TEST(Settling, WaitTimeExpiresOnExactStep) {
  // 25 ms (the default, manual 6.2) at 0.1 ms steps: done exactly 250 steps after entry,
  // not one step late from float accumulation.
  SettlingMonitor m;
  m.start(params(1.0, 0.025, 1.0));
  EXPECT_EQ(m.update(0.0, kDt), SettlingResult::Settling); // (c), clock 0
  EXPECT_EQ(feed(m, 0.0, 249), SettlingResult::Settling);
  EXPECT_EQ(m.update(0.0, kDt), SettlingResult::Done);
  EXPECT_NEAR(m.settling_time_s(), 0.0251, 1e-12);
}

TEST(Settling, TimeoutCountsFromBToF) {
  // manual 3.5.8: the timeout limits the settling time; travel time not included.
  SettlingMonitor m;
  m.start(params(1.0, 0.001, 0.1));
  EXPECT_EQ(feed(m, 2.0, 999), SettlingResult::Settling);
  EXPECT_EQ(m.update(2.0, kDt), SettlingResult::Timeout); // 100 ms after (b)
  EXPECT_EQ(m.update(0.0, kDt), SettlingResult::Timeout); // sticky
}

TEST(Settling, TimeoutWhileWaitingInsideTheWindow) {
  // Inside the window but the wait time does not fit before the timeout: still an error.
  SettlingMonitor m;
  m.start(params(1.0, 0.05, 0.1));
  EXPECT_EQ(feed(m, 2.0, 600), SettlingResult::Settling);
  EXPECT_EQ(feed(m, 0.0, 400), SettlingResult::Timeout);
}

TEST(Settling, CompletionAtTheTimeoutInstantCountsAsDone) {
  SettlingMonitor m;
  m.start(params(1.0, 0.0, 0.1));
  EXPECT_EQ(feed(m, 2.0, 999), SettlingResult::Settling);
  EXPECT_EQ(m.update(0.0, kDt), SettlingResult::Done); // at 100 ms exactly
}

TEST(Settling, TimeoutDisabledWaitsForever) {
  // manual 3.5.8 Timeout Enable = 0.
  SettlingMonitor m;
  m.start(params(1.0, 0.01, 0.1, false));
  EXPECT_EQ(feed(m, 2.0, 100000), SettlingResult::Settling); // 10 s outside
  EXPECT_EQ(feed(m, 0.0, 101), SettlingResult::Done);
  EXPECT_NEAR(m.settling_time_s(), 10.0101, 1e-9);
}

TEST(Settling, StartResetsEverything) {
  SettlingMonitor m;
  m.start(params(1.0, 0.0, 0.0));
  EXPECT_EQ(m.update(2.0, kDt), SettlingResult::Timeout);
  m.start(params(1.0, 0.0, 0.1));
  EXPECT_EQ(m.result(), SettlingResult::Settling);
  EXPECT_EQ(m.settling_time_s(), 0.0);
  EXPECT_EQ(m.update(0.5, kDt), SettlingResult::Done);
}

} // namespace
} // namespace sreh
