// Manual 3.4 (position modes), 4.1 (multiturn), 4.2 (direction), 4.3 (zero
// offset), 6.2 index 81 (position limit), 2.5 (position coding).
#include <gtest/gtest.h>

#include "tests/device_logic/device_rig.hpp"

namespace sreh::test {
namespace {


TEST(PositionModes, Absolute_3_4) {
  Rig r;
  r.switch_on();
  ASSERT_TRUE(r.move_to_deg(120));
  EXPECT_NEAR(r.position_deg(), 120, 0.1);
  r.release_move();
  ASSERT_TRUE(r.move_to_deg(-45));
  EXPECT_NEAR(r.position_deg(), -45, 0.1);
}

TEST(PositionModes, RelativeFromLastTargetNotActualPosition_3_4) {
  Rig r;
  r.switch_on();
  r.pd.relative = true;
  ASSERT_TRUE(r.move_to_deg(30)); // first move after switching on: from the actual position
  r.release_move();
  // Push the flange a little off the target (within the tolerance of nothing in particular).
  const double off = r.position_deg() - 30.0;
  ASSERT_TRUE(r.move_to_deg(30));
  r.release_move();
  ASSERT_TRUE(r.move_to_deg(30));
  // Three relative moves of 30 deg end at 90 deg from the last target, no error accumulates.
  EXPECT_NEAR(r.position_deg(), 90.0, 0.1);
  EXPECT_LT(std::abs(off), 0.1);
}

TEST(PositionModes, RelativeFirstMoveAfterSwitchOnStartsAtActual_3_4) {
  Rig r;
  r.switch_on();
  ASSERT_TRUE(r.move_to_deg(50));
  r.release_move();
  r.pd.motor_on = false;
  r.cycle();
  r.angle_rad = deg_to_rad(70.0); // turned by hand while off
  r.vel_rad_s = 0;
  r.cycle();
  r.switch_on();
  r.pd.relative = true;
  ASSERT_TRUE(r.move_to_deg(10));
  EXPECT_NEAR(r.position_deg(), 80.0, 0.1); // from the actual 70, not the old target 50
}

TEST(PositionModes, ShortestPath300To20Gives380_3_4) {
  Rig r;
  r.switch_on();
  ASSERT_TRUE(r.move_to_deg(300));
  r.release_move();
  r.pd.shortest_path = true;
  ASSERT_TRUE(r.move_to_deg(20));
  EXPECT_NEAR(r.position_deg(), 380.0, 0.1); // manual 3.4 example
}

TEST(PositionModes, ShortestPathUsesOnlyLow16BitsAndAtMost180_3_4) {
  Rig r;
  r.switch_on();
  r.pd.shortest_path = true;
  // Target 3 revolutions + 350 deg: only 350 deg counts, reached by -10 deg.
  ASSERT_TRUE(r.move_to_deg(3 * 360.0 + 350.0));
  EXPECT_NEAR(r.position_deg(), -10.0, 0.1);
}

// A-POS-2: exactly 180 deg goes in the positive direction.
TEST(PositionModes, ShortestPathExactly180GoesPositive_3_4) {
  Rig r;
  r.switch_on();
  r.pd.shortest_path = true;
  ASSERT_TRUE(r.move_to_deg(180.0));
  EXPECT_NEAR(r.position_deg(), 180.0, 0.1);
}

TEST(PositionModes, RelativeWithShortestPathRefusedWithCode3_7_2_114_7) {
  Rig r;
  r.switch_on();
  r.pd.relative = true;
  r.pd.shortest_path = true;
  EXPECT_FALSE(r.move_to_deg(20));
  EXPECT_EQ(r.state(), State::ErrorOn);
  EXPECT_EQ(r.read_u(114, 7), 3);
  EXPECT_NEAR(r.position_deg(), 0.0, 0.05);
}

TEST(PositionModes, ParameterSetAbove7RefusedWithCode2_7_2_114_7) {
  Rig r;
  r.switch_on();
  EXPECT_FALSE(r.move_to_deg(20, 8));
  EXPECT_EQ(r.read_u(114, 7), 2);
}

TEST(PositionLimit, TargetOutsideRefusedBeforeMotion_6_2_81) {
  Rig r;
  ASSERT_TRUE(r.write_u(81, 3, 1).ok()); // active, 0..360 deg by default
  r.switch_on();
  EXPECT_FALSE(r.move_to_deg(400));
  EXPECT_EQ(r.state(), State::ErrorOn);
  EXPECT_EQ(r.read_u(114, 7), 1);
  EXPECT_EQ(r.in.error_code, 1u << 1);
  r.run_s(0.05);
  EXPECT_NEAR(r.position_deg(), 0.0, 0.05); // no motion at all
}

TEST(PositionLimit, AppliesToRelativeAndShortestPathToo_6_2_81) {
  Rig r;
  ASSERT_TRUE(r.write_u(81, 3, 1).ok());
  r.switch_on();
  ASSERT_TRUE(r.move_to_deg(350));
  r.release_move();
  r.pd.relative = true;
  EXPECT_FALSE(r.move_to_deg(20)); // 370 deg
  EXPECT_EQ(r.read_u(114, 7), 1);
  r.pd.move = false;
  r.pd.relative = false;
  r.pd.reset_error = true;
  r.cycle();
  r.pd.reset_error = false;
  r.cycle();
  ASSERT_EQ(r.state(), State::Ready);
  r.pd.shortest_path = true;
  EXPECT_FALSE(r.move_to_deg(10)); // nearest 10 deg is 370 deg
  EXPECT_EQ(r.read_u(114, 7), 1);
}

TEST(PositionLimit, InactiveLimitAllowsAnyTarget_6_2_81) {
  Rig r;
  r.switch_on();
  ASSERT_TRUE(r.move_to_deg(400));
}

TEST(Multiturn, PowerUpWithin720_1080BecomesMinus360_4_1) {
  Rig r;
  r.switch_on();
  ASSERT_TRUE(r.move_to_deg(1080, 1, 5.0));
  EXPECT_NEAR(r.position_deg(), 1080, 0.1);
  r.release_move();
  r.pd.motor_on = false;
  r.cycle();
  r.power_cycle();
  r.cycle();
  EXPECT_NEAR(r.position_deg(), -360, 0.1); // manual 4.1 example
}

TEST(Multiturn, MovedWhileSwitchedOffIsTracked_4_1) {
  Rig r;
  r.dev.power_off();
  r.angle_rad = deg_to_rad(500.0); // turned by hand while off
  r.dev.power_on(r.sensors());
  r.cycle();
  EXPECT_NEAR(r.position_deg(), 500.0, 0.01);
  r.dev.power_off();
  r.angle_rad = deg_to_rad(-719.0);
  r.dev.power_on(r.sensors());
  r.cycle();
  EXPECT_NEAR(r.position_deg(), -719.0, 0.01);
  r.dev.power_off();
  r.angle_rad = deg_to_rad(720.0); // A-POS-1: +720 maps to -720
  r.dev.power_on(r.sensors());
  r.cycle();
  EXPECT_NEAR(r.position_deg(), -720.0, 0.01);
}

TEST(ZeroOffset, SetOriginIsVolatile_4_3_2) {
  Rig r;
  r.switch_on();
  ASSERT_TRUE(r.move_to_deg(100));
  r.release_move();
  r.set_origin_pulse();
  EXPECT_NEAR(r.position_deg(), 0.0, 0.1);
  r.pd.motor_on = false;
  r.cycle();
  r.power_cycle();
  r.cycle();
  EXPECT_NEAR(r.position_deg(), 100.0, 0.1); // lost on power-off
}

TEST(ZeroOffset, StoreOrigin171Persists_4_3_2_6_6) {
  Rig r;
  r.switch_on();
  ASSERT_TRUE(r.move_to_deg(100));
  r.release_move();
  r.set_origin_pulse();
  ASSERT_TRUE(r.command(171).ok());
  EXPECT_NEAR(static_cast<double>(r.read_u(86, 0)), static_cast<double>(deg_to_wire_counts(100.0)), 20.0);
  r.pd.motor_on = false;
  r.cycle();
  r.power_cycle();
  r.cycle();
  EXPECT_NEAR(r.position_deg(), 0.0, 0.1);
}

TEST(ZeroOffset, Writing86StoresAndApplies_4_3_2) {
  Rig r;
  r.angle_rad = deg_to_rad(30.0);
  r.power_cycle();
  r.cycle();
  ASSERT_TRUE(r.write_u(86, 0, deg_to_wire_counts(10.0)).ok());
  r.cycle();
  EXPECT_NEAR(r.position_deg(), 20.0, 0.01);
  r.power_cycle();
  r.cycle();
  EXPECT_NEAR(r.position_deg(), 20.0, 0.01);
}

TEST(ZeroOffset, Command170ReinitialisesFromStoredOffset_4_3_3) {
  Rig r;
  r.angle_rad = deg_to_rad(30.0);
  r.power_cycle();
  r.switch_on();
  r.set_origin_pulse();
  ASSERT_NEAR(r.position_deg(), 0.0, 0.01);
  ASSERT_TRUE(r.command(170).ok()); // back to the stored offset 0
  r.cycle();
  EXPECT_NEAR(r.position_deg(), 30.0, 0.01);
}

TEST(Direction, CounterclockwiseFlipsSign_4_2) {
  Rig r;
  ASSERT_TRUE(r.write_u(82, 0, 1).ok());
  r.switch_on();
  ASSERT_TRUE(r.move_to_deg(90));
  EXPECT_NEAR(r.position_deg(), 90.0, 0.1);
  EXPECT_NEAR(rad_to_deg(r.angle_rad), -90.0, 0.1); // the flange turned the other way
}

TEST(PositionCoding, WrapsBeyond2Pow15Revolutions_2_5) {
  Rig r;
  r.dev.power_off();
  r.angle_rad = 0;
  r.dev.power_on(r.sensors());
  // Zero offset -720 deg, then a hand turn far beyond: the int32 wraps.
  r.cycle();
  r.dev.power_off();
  const double revs = 32768.0 + 0.25; // 2^15 revolutions plus 90 deg
  r.angle_rad = 2 * kPi * revs;
  r.dev.power_on(r.sensors()); // multiturn folds it into +-720 deg at power-up
  r.cycle();
  EXPECT_NEAR(r.position_deg(), 90.0, 0.01);
}

} // namespace
} // namespace sreh::test
