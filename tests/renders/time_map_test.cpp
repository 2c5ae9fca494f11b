// Automatic time scaling of videos (issue 16, A-RENDERS-12).
#include "renders/time_map.hpp"

#include <gtest/gtest.h>

namespace sreh {
namespace {

TEST(NiceFactor, RoundsUpToOneOfTheSteps) {
  EXPECT_EQ(nice_factor_up(0.5), 1.0);
  EXPECT_EQ(nice_factor_up(1.0), 1.0);
  EXPECT_EQ(nice_factor_up(1.2), 1.5);
  EXPECT_EQ(nice_factor_up(16.7), 20.0);
  EXPECT_EQ(nice_factor_up(7.0), 8.0);
  EXPECT_EQ(nice_factor_up(81.0), 100.0);
}

TEST(TimeMap, ConstantSlowMotionScalesEverything) {
  const TimeMap m = TimeMap::constant(4.0, 2.0);
  EXPECT_DOUBLE_EQ(m.video_duration_s(), 8.0);
  EXPECT_DOUBLE_EQ(m.video_time(0.5), 2.0);
  EXPECT_DOUBLE_EQ(m.sim_time(2.0), 0.5);
  EXPECT_EQ(m.segment_at(1.0).label(), "slow motion 4x");
}

TEST(TimeMap, ShortMoveIsSlowedToTheMinimumOnScreenDuration) {
  // A 90 ms move in a 0.5 s run: 1.5 s / 0.09 s = 16.7 -> 20x.
  TimeScaleOptions o;
  o.min_move_video_s = 1.5;
  const TimeMap m = TimeMap::automatic({{0.1, 0.19}}, 0.5, o);
  const TimeSegment& s = m.segment_at(0.15);
  EXPECT_EQ(s.kind, TimeSegment::Kind::SlowMotion);
  EXPECT_EQ(s.rate, 20.0);
  EXPECT_GE(m.video_time(0.19) - m.video_time(0.1), 1.5);
  // Padding at the move's rate: 0.3 s of video either side.
  EXPECT_NEAR(m.video_time(0.1) - m.video_time(0.1 - 0.3 / 20), 0.3, 1e-9);
  EXPECT_EQ(m.segment_at(0.01).kind, TimeSegment::Kind::RealTime);
  EXPECT_EQ(m.segment_at(0.45).kind, TimeSegment::Kind::RealTime);
}

TEST(TimeMap, LongMovesPlayInRealTime) {
  const TimeMap m = TimeMap::automatic({{1.0, 4.0}}, 5.0);
  EXPECT_EQ(TimeScaleOptions{}.min_move_video_s, 2.0); // the default: 2 s on screen at least
  EXPECT_DOUBLE_EQ(m.video_duration_s(), 5.0);
  EXPECT_EQ(m.segments().size(), 1u);
}

TEST(TimeMap, LongIdleIsCompressedAndMarked) {
  const TimeMap m = TimeMap::automatic({{0.1, 0.3}, {30.1, 30.3}}, 31.0);
  const TimeSegment& idle = m.segment_at(15.0);
  EXPECT_EQ(idle.kind, TimeSegment::Kind::FastForward);
  EXPECT_NEAR((idle.t1_s - idle.t0_s) * idle.rate, 1.0, 1e-9);
  EXPECT_NE(idle.label().find("fast forward"), std::string::npos);
  EXPECT_LT(m.video_duration_s(), 10.0);
}

TEST(TimeMap, VideoTimeAndSimTimeAreInverseAndMonotonic) {
  const TimeMap m = TimeMap::automatic({{0.1, 0.15}, {0.16, 0.2}, {0.5, 0.52}, {9.0, 9.4}}, 10.0);
  double last = -1;
  for (double t = 0; t <= 10.0; t += 0.001) {
    const double v = m.video_time(t);
    EXPECT_GT(v, last);
    last = v;
    EXPECT_NEAR(m.sim_time(v), t, 1e-9);
  }
}

TEST(TimeMap, SlowMotionIsCapped) {
  const TimeMap m = TimeMap::automatic({{0.1, 0.1001}}, 0.3);
  EXPECT_EQ(m.segment_at(0.1).rate, 100.0);
}

// Issue 39 (A-RENDERS-20): moves share one factor, so that their on-screen
// durations compare: a 0.1 s swivel wants 20x, a 0.3 s move alone 6.67x
// (within 5x): both play at 20x.
TEST(TimeMap, MovesShareOneFactor) {
  const TimeMap m = TimeMap::automatic({{0.1, 0.2}, {1.0, 1.3}}, 1.5);
  EXPECT_EQ(m.segment_at(0.15).rate, 20.0);
  EXPECT_EQ(m.segment_at(1.15).rate, 20.0);
  EXPECT_EQ(m.slowmo_factors(), std::vector<double>{20.0});
  EXPECT_NEAR((m.video_time(1.3) - m.video_time(1.0)) / (m.video_time(0.2) - m.video_time(0.1)), 3.0, 1e-9);
  EXPECT_EQ(m.describe(), "slow motion 20x for every move");
  for (const TimeSegment& s : m.segments()) EXPECT_EQ(s.label().find("was"), std::string::npos) << s.label();
}

// A move over 5x longer than the shortest gets its own factor, which the
// banner names where it changes, and the title card lists.
TEST(TimeMap, MuchLongerMoveGetsItsOwnNamedFactor) {
  const TimeMap m = TimeMap::automatic({{0.1, 0.15}, {1.0, 2.0}}, 2.5);
  EXPECT_EQ(m.segment_at(0.12).rate, 40.0);
  EXPECT_EQ(m.segment_at(1.5).rate, 2.0);
  EXPECT_EQ(m.segment_at(1.5).label(), "slow motion 2x (was 40x)");
  EXPECT_EQ(m.segment_at(0.12).label(), "slow motion 40x");
  EXPECT_EQ(m.slowmo_factors(), (std::vector<double>{40.0, 2.0}));
  EXPECT_EQ(m.describe(), "slow motion 40x and 2x (moves differ more than 5x in length)");
  TimeScaleOptions wide;
  wide.max_factor_ratio = 100; // within the ratio: one factor again
  EXPECT_EQ(TimeMap::automatic({{0.1, 0.15}, {1.0, 2.0}}, 2.5, wide).slowmo_factors(), std::vector<double>{40.0});
}

} // namespace
} // namespace sreh
