// Move records (issue 13, manual 3.5.2 Fig. 3): times from (a), (b), (f) on
// the integer clock, settling never negative, positioning = travel +
// settling, overshoot in the direction of travel, per-move settling
// parameters, the window watched while the target is held (3.5.7).
#include <gtest/gtest.h>

#include <cmath>

#include "device_logic/move_record.hpp"

namespace sreh {
namespace {

constexpr int64_t kMs = 1'000'000;

MoveRecorder::Start start_at(int64_t ns, double from, double to) {
  MoveRecorder::Start s;
  s.now_ns = ns;
  s.parameter_set = 3;
  s.start_deg = from;
  s.target_deg = to;
  s.tolerance_deg = 0.05;
  s.wait_ms = 2.5;
  s.settling_timeout_ms = 100;
  return s;
}

MoveRecord only(MoveRecorder& r) {
  r.release();
  auto v = r.take_finished();
  EXPECT_EQ(v.size(), 1u);
  return v.empty() ? MoveRecord{} : v[0];
}

TEST(MoveRecord, DoneMoveHasTravelSettlingPositioning_3_5_2) {
  MoveRecorder r;
  r.start(start_at(10 * kMs, 0, 90));
  r.step(11 * kMs, std::abs(40 - 39.9), 39.9, true);
  r.step(372 * kMs, std::abs(90 - 89.93), 89.93, false); // (b) 362 ms after (a), outside the window
  r.step(373 * kMs, std::abs(90 - 90.02), 90.02, false); // inside from here, past the target: overshoot 0.02
  r.step(374 * kMs, std::abs(90 - 90.01), 90.01, false);
  r.finish(377 * kMs, MoveOutcome::Done, 90.0);
  EXPECT_TRUE(r.holding());
  EXPECT_TRUE(r.take_finished().empty()); // held while the target is held
  const MoveRecord m = only(r);
  EXPECT_EQ(m.number, 1u);
  EXPECT_EQ(m.parameter_set, 3);
  EXPECT_DOUBLE_EQ(m.target_deg, 90);
  EXPECT_DOUBLE_EQ(m.end_deg, 90.0);
  EXPECT_DOUBLE_EQ(m.travel_s, 0.362); // one division of integer ns: prints as 0.362
  ASSERT_TRUE(m.settling_s && m.positioning_s && m.in_window_s);
  EXPECT_DOUBLE_EQ(*m.settling_s, 0.005);
  EXPECT_DOUBLE_EQ(*m.positioning_s, 0.367);
  EXPECT_DOUBLE_EQ(*m.in_window_s, 0.001);
  EXPECT_NEAR(m.overshoot_deg, 0.02, 1e-12);
  EXPECT_NEAR(m.max_tracking_error_deg, 0.1, 1e-12);
  EXPECT_DOUBLE_EQ(m.tolerance_deg, 0.05);
  EXPECT_DOUBLE_EQ(m.wait_ms, 2.5);
  EXPECT_TRUE(m.completed());
}

TEST(MoveRecord, LeavingTheWindowWhileHeldClearsInWindow_3_5_7) {
  MoveRecorder r;
  r.start(start_at(0, 0, 10));
  r.step(kMs, std::abs(10 - 10.0), 10.0, false);
  r.finish(kMs, MoveOutcome::Done, 10.0);
  r.step(5 * kMs, std::abs(10 - 10.2), 10.2, false); // swings out after Done (115.3): overshoot seen while held
  const MoveRecord m = only(r);
  EXPECT_FALSE(m.in_window_s.has_value());
  EXPECT_NEAR(m.overshoot_deg, 0.2, 1e-12);
  EXPECT_DOUBLE_EQ(*m.settling_s, 0.0);
}

TEST(MoveRecord, NegativeMoveOvershootsBelowTheTarget) {
  MoveRecorder r;
  r.start(start_at(0, 90, 0));
  r.step(kMs, std::abs(0 - -0.03), -0.03, false);
  r.step(2 * kMs, std::abs(0 - 0.01), 0.01, false); // short of the target: not an overshoot
  r.finish(3 * kMs, MoveOutcome::Done, 0.0);
  EXPECT_NEAR(only(r).overshoot_deg, 0.03, 1e-12);
}

TEST(MoveRecord, ErrorMoveHasNoSettlingTime_7_2) {
  MoveRecorder r;
  r.start(start_at(0, 0, 120));
  r.step(50 * kMs, std::abs(60 - 58), 58, true);
  r.finish(51 * kMs, MoveOutcome::Error, 58.5, 0x08);
  EXPECT_FALSE(r.holding()); // handed out at once
  const auto v = r.take_finished();
  ASSERT_EQ(v.size(), 1u);
  const MoveRecord& m = v[0];
  EXPECT_FALSE(m.completed());
  EXPECT_EQ(m.outcome, MoveOutcome::Error);
  EXPECT_EQ(m.error_code, 0x08);
  EXPECT_FALSE(m.settling_s.has_value());
  EXPECT_FALSE(m.positioning_s.has_value());
  EXPECT_DOUBLE_EQ(m.travel_s, 0.051);
  EXPECT_DOUBLE_EQ(m.end_deg, 58.5);
  EXPECT_DOUBLE_EQ(m.target_deg, 120); // the commanded target, not where travel ended
}

TEST(MoveRecord, ZeroLengthMoveHasNoOvershootAndZeroTravel_3_5_2) {
  MoveRecorder r;
  r.start(start_at(5 * kMs, 10, 10));
  r.step(5 * kMs, std::abs(10 - 10.01), 10.01, false);
  r.finish(30 * kMs, MoveOutcome::Done, 10.0);
  const MoveRecord m = only(r);
  EXPECT_DOUBLE_EQ(m.travel_s, 0);
  EXPECT_DOUBLE_EQ(*m.settling_s, 0.025);
  EXPECT_DOUBLE_EQ(m.overshoot_deg, 0);
}

TEST(MoveRecord, NextMoveHandsOutTheHeldOneAndNumbers) {
  MoveRecorder r;
  r.start(start_at(0, 0, 1));
  r.mark_stopped();
  r.step(kMs, std::abs(0.5 - 0.5), 0.5, false);
  r.finish(2 * kMs, MoveOutcome::Done, 0.5);
  r.start(start_at(3 * kMs, 0.5, 1));
  EXPECT_TRUE(r.open());
  ASSERT_TRUE(r.pending());
  EXPECT_EQ(r.pending()->number, 2u);
  const auto v = r.take_finished();
  ASSERT_EQ(v.size(), 1u);
  EXPECT_TRUE(v[0].stopped);
  EXPECT_TRUE(r.take_finished().empty());
}

} // namespace
} // namespace sreh
