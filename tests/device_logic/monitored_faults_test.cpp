// The whole Device answering what its monitors see (errors, warnings, what
// the state machine does with them); each monitor alone is in
// monitor_steps_test.cpp.
// Monitors: motor voltage (6.2 index 85, 7.2 114.4, 7.3 115.2), temperature
// (7.2 114.3, 7.3 115.1), tracking error (6.2 index 87, 7.2 114.5), settling
// (3.5.7, 3.5.8, 7.2 114.8, 7.3 115.3), connection loss and invalid process
// data (5, 7.2 114.6 codes 16 / 17).
#include <gtest/gtest.h>

#include "tests/device_logic/device_rig.hpp"

namespace sreh::test {
namespace {

constexpr uint8_t kErrBit(int b) { return static_cast<uint8_t>(1u << b); }

TEST(Voltage, TooLowWithMotorOnIsErrorMotorOff_7_2_114_4) {
  Rig r;
  r.switch_on();
  r.supply_V = 17.0; // below 85.1 = 18 V
  r.run_s(0.01);
  EXPECT_EQ(r.state(), State::ErrorOff);
  EXPECT_EQ(r.in.error_code, kErrBit(4));
  EXPECT_EQ(r.read_u(114, 4), 1);
}

TEST(Voltage, TooHighWithMotorOnIsErrorCode2_7_2_114_4) {
  Rig r;
  r.switch_on();
  r.supply_V = 31.0;
  r.run_s(0.01);
  EXPECT_EQ(r.state(), State::ErrorOff);
  EXPECT_EQ(r.read_u(114, 4), 2);
}

TEST(Voltage, OutOfRangeWithMotorOffIsSelfClearingWarning_7_3_115_2) {
  Rig r;
  r.supply_V = 17.0;
  r.run_s(0.01);
  EXPECT_EQ(r.state(), State::MotorOff);
  EXPECT_EQ(r.in.warning_code, 1u << 6);
  EXPECT_TRUE(r.in.warning);
  EXPECT_EQ(r.read_u(115, 2), 1);
  r.supply_V = 31.0;
  r.run_s(0.01);
  EXPECT_EQ(r.read_u(115, 2), 2);
  r.supply_V = 24.0;
  r.run_s(0.01);
  EXPECT_EQ(r.in.warning_code, 0); // manual 3.3: warnings clear themselves
  EXPECT_EQ(r.read_u(115, 2), 0);
}

TEST(Voltage, ConfiguredRangeIsUsed_6_2_85) {
  Rig r;
  ASSERT_TRUE(r.write_u(85, 1, 23000).ok());
  r.switch_on();
  r.supply_V = 22.5;
  r.run_s(0.01);
  EXPECT_EQ(r.read_u(114, 4), 1);
}

TEST(Temperature, WarningAt70ClearsBelow_7_3_115_1) {
  Rig r;
  r.switch_on();
  r.temperature_C = 70.0;
  r.cycle();
  r.cycle();
  EXPECT_EQ(r.state(), State::Ready);
  EXPECT_EQ(r.in.warning_code, 1u << 7);
  EXPECT_EQ(r.read_u(115, 1), 1);
  r.temperature_C = 60.0;
  r.cycle();
  r.cycle();
  EXPECT_EQ(r.in.warning_code, 0);
}

TEST(Temperature, ErrorAt75SwitchesMotorOff_7_2_114_3) {
  Rig r;
  r.switch_on();
  r.temperature_C = 75.0;
  r.cycle();
  r.cycle();
  EXPECT_EQ(r.state(), State::ErrorOff);
  EXPECT_EQ(r.in.error_code, kErrBit(5));
  EXPECT_EQ(r.read_u(114, 3), 1);
  EXPECT_EQ(r.read_u(112, 0), 150); // 0.5 C raw
}

TEST(TrackingError, WrongLoadConfigurationTripsIt_7_2_114_5) {
  Rig r;
  r.load_kgm2 = gcm2_to_kgm2(15000); // heavy load, parameter set 1 thinks 0 g cm^2
  r.switch_on();
  EXPECT_FALSE(r.move_to_deg(180));
  EXPECT_EQ(r.state(), State::ErrorOff);
  EXPECT_EQ(r.in.error_code, kErrBit(3));
  EXPECT_EQ(r.read_u(114, 5), 64);
}

TEST(TrackingError, CorrectLoadConfigurationTracks_3_5_6) {
  Rig r;
  r.load_kgm2 = gcm2_to_kgm2(15000);
  ASSERT_TRUE(r.write_u(65, 4, 15000).ok());
  r.switch_on();
  EXPECT_TRUE(r.move_to_deg(180));
  EXPECT_EQ(r.in.error_code, 0);
}

TEST(TrackingError, MonitoringCanBeDisabled_6_2_87) {
  Rig r;
  ASSERT_TRUE(r.write_u(87, 2, 0).ok());
  r.switch_on();
  r.external_Nm = 2.0; // far more than the motor can hold
  r.run_s(0.05);
  EXPECT_EQ(r.in.error_code & kErrBit(3), 0);
  ASSERT_TRUE(r.write_u(87, 2, 1).ok());
  r.run_s(0.01);
  EXPECT_EQ(r.read_u(114, 5), 64);
}

TEST(TrackingError, TooFastForLowVoltage_3_5_3) {
  // At 19 V the motor cannot reach 4300 deg/s (manual 3.5.3): a tracking error.
  for (double volts : {24.0, 19.0}) {
    Rig r;
    ASSERT_TRUE(r.write_u(65, 1, 43000).ok());
    r.supply_V = volts;
    r.switch_on();
    const bool done = r.move_to_deg(1080, 1, 3.0);
    if (volts == 24.0) {
      EXPECT_TRUE(done) << r.read_u(114, 5);
    } else {
      EXPECT_FALSE(done);
      EXPECT_EQ(r.read_u(114, 5), 64);
    }
  }
}

TEST(Settling, TimeoutIsPositioningErrorMotorStaysOn_3_5_8_114_8) {
  Rig r;
  ASSERT_TRUE(r.write_u(87, 2, 0).ok());      // no tracking monitor
  ASSERT_TRUE(r.write_u(65, 5, 1).ok());      // tolerance 1 count: unreachable
  ASSERT_TRUE(r.write_u(65, 7, 200).ok());    // 20 ms timeout
  r.switch_on();
  EXPECT_FALSE(r.move_to_deg(90));
  EXPECT_EQ(r.state(), State::ErrorOn);
  EXPECT_EQ(r.in.error_code, kErrBit(0));
  EXPECT_EQ(r.read_u(114, 8), 1);
}

// A vibrating disturbance keeps the flange out of a 1-count window: with the
// timeout disabled the module waits in Busy, with it enabled it fails.
TEST(Settling, TimeoutDisabledWaitsForever_3_5_8) {
  for (int enabled = 0; enabled <= 1; ++enabled) {
    Rig r;
    ASSERT_TRUE(r.write_u(65, 5, 1).ok());
    ASSERT_TRUE(r.write_u(65, 7, 100).ok());
    ASSERT_TRUE(r.write_u(65, 8, enabled).ok());
    r.switch_on();
    r.start_move(90);
    for (int i = 0; i < 250; ++i) {
      r.external_Nm = (i % 2) ? 0.05 : -0.05;
      r.cycle();
    }
    if (enabled) {
      EXPECT_EQ(r.read_u(114, 8), 1);
    } else {
      EXPECT_EQ(r.state(), State::Busy);
      EXPECT_EQ(r.in.error_code, 0);
    }
  }
}

TEST(Settling, RelativeAfterPositioningErrorStartsAtActual_3_4) {
  Rig r;
  ASSERT_TRUE(r.write_u(65, 5, 1).ok());
  ASSERT_TRUE(r.write_u(65, 7, 100).ok());
  r.switch_on();
  r.pd.relative = true;
  EXPECT_FALSE(r.move_to_deg(90));
  ASSERT_EQ(r.read_u(114, 8), 1);
  const double actual = r.position_deg();
  r.pd.move = false;
  r.pd.reset_error = true;
  r.cycle();
  r.pd.reset_error = false;
  r.cycle();
  ASSERT_TRUE(r.write_u(66, 5, 146).ok()); // set 2: default tolerance
  r.pd.relative = true;
  ASSERT_TRUE(r.move_to_deg(10, 2));
  EXPECT_NEAR(r.position_deg(), actual + 10.0, 0.1);
}

TEST(Settling, LeavingWindowAfterDoneWarnsUntilNextMove_3_5_7_115_3) {
  Rig r;
  r.switch_on();
  ASSERT_TRUE(r.move_to_deg(90));
  EXPECT_EQ(r.in.warning_code, 0);
  r.external_Nm = 0.5; // a moment on the flange pushes it out of the 0.1 deg window
  r.run_s(0.002);
  r.external_Nm = 0.0;
  r.run_s(0.2);
  EXPECT_EQ(r.in.warning_code, 1u << 5);
  EXPECT_EQ(r.read_u(115, 3), 1);
  EXPECT_EQ(r.state(), State::Done); // a warning, not a state
  r.release_move();
  EXPECT_EQ(r.in.warning_code, 1u << 5); // stays until the next move
  ASSERT_TRUE(r.move_to_deg(0));
  EXPECT_EQ(r.in.warning_code, 0);
}

TEST(Settling, PositioningWarningClearedByMotorOff_3_5_7) {
  Rig r;
  r.switch_on();
  ASSERT_TRUE(r.move_to_deg(90));
  r.external_Nm = 0.5;
  r.run_s(0.002);
  r.external_Nm = 0.0;
  r.release_move();
  ASSERT_EQ(r.in.warning_code, 1u << 5);
  r.pd.motor_on = false;
  r.cycle();
  r.cycle();
  EXPECT_EQ(r.in.warning_code, 0);
}

TEST(ConnectionLoss, MotorOnGoesErrorOffCode16_5) {
  Rig r;
  r.switch_on();
  r.link_up = false;
  r.run_s(0.1);
  r.link_up = true;
  r.cycle();
  EXPECT_EQ(r.state(), State::ErrorOff);
  EXPECT_EQ(r.read_u(114, 6), 16);
}

TEST(ConnectionLoss, MotorOffIsNoError_5) {
  Rig r;
  r.cycle();
  r.link_up = false;
  r.run_s(0.1);
  r.link_up = true;
  r.cycle();
  EXPECT_EQ(r.state(), State::MotorOff);
  EXPECT_EQ(r.in.error_code, 0);
}

// A-LINK-1: a few missed cycles are tolerated.
TEST(ConnectionLoss, ShortGapBelowWatchdogIsTolerated_5) {
  Rig r;
  r.switch_on();
  r.link_up = false;
  r.run_s(0.01);
  r.link_up = true;
  r.cycle();
  EXPECT_EQ(r.state(), State::Ready);
}

TEST(InvalidOutputs, MotorOnGoesErrorOffCode17_5) {
  Rig r;
  r.switch_on();
  r.outputs_valid = false;
  r.cycle();
  EXPECT_EQ(r.state(), State::ErrorOff);
  EXPECT_EQ(r.read_u(114, 6), 17);
}

TEST(InvalidOutputs, IgnoredWhileInvalidNoErrorWithMotorOff_5) {
  Rig r;
  r.cycle();
  r.outputs_valid = false;
  r.pd.motor_on = true; // ignored
  r.run_s(0.02);
  EXPECT_EQ(r.state(), State::MotorOff);
  EXPECT_EQ(r.in.error_code, 0);
  r.outputs_valid = true;
  r.cycle();
  EXPECT_EQ(r.state(), State::Ready);
}

} // namespace
} // namespace sreh::test
