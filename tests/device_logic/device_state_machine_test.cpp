// Manual 3.1 / 3.2: every transition of the state machine and the invalid
// command sequences of manual 7.2 (114.6), driven through process data only.
#include <gtest/gtest.h>

#include <set>

#include "device_logic/state_machine.hpp"
#include "tests/device_logic/device_rig.hpp"

namespace sreh::test {
namespace {

uint8_t cause114(Rig& r, uint8_t sub) { return static_cast<uint8_t>(r.read_u(114, sub)); }

TEST(StateMachine, FactoryNewDeviceIsMotorOff_3_1) {
  Rig r;
  r.cycle();
  EXPECT_EQ(r.state(), State::MotorOff);
  EXPECT_TRUE(r.in.motor_off);
  EXPECT_FALSE(r.in.ready || r.in.busy || r.in.done || r.in.error);
}

TEST(StateMachine, T1_SwitchOnGoesReady_T2_SwitchOffGoesMotorOff) {
  Rig r;
  r.switch_on();
  EXPECT_EQ(r.state(), State::Ready);
  EXPECT_FALSE(r.in.motor_off);
  r.pd.motor_on = false;
  r.cycle();
  EXPECT_EQ(r.state(), State::MotorOff);
  EXPECT_EQ(r.in.error_code, 0);
}

// A-SM-1: Motor On while Error Reset is already set is refused (manual 3.2
// T1: Move, Error Reset and Set Origin must be 0); the device stays MotorOff
// without an error and switches on once the bit is 0.
TEST(StateMachine, T1_RefusedWhileErrorResetSet) {
  Rig r;
  r.pd.reset_error = true;
  r.cycle();
  r.pd.motor_on = true;
  r.run_s(0.02);
  EXPECT_EQ(r.state(), State::MotorOff);
  EXPECT_EQ(r.in.error_code, 0);
  r.pd.reset_error = false;
  r.cycle();
  EXPECT_EQ(r.state(), State::Ready);
}

// Move or Set Origin set together with Motor On: the command rises in
// MotorOff, which is not Ready (manual 7.2, 114.6 codes 4 / 5).
TEST(StateMachine, T1_WithMoveRaisesMoveFromInvalidState) {
  Rig r;
  r.pd.motor_on = true;
  r.pd.move = true;
  r.cycle();
  EXPECT_EQ(r.state(), State::ErrorOff);
  EXPECT_EQ(r.read_u(114, 6), 4);
}

TEST(StateMachine, T3_T5_T7_MoveBusyDoneReady) {
  Rig r;
  r.switch_on();
  r.start_move(90);
  r.cycle();
  EXPECT_EQ(r.state(), State::Busy); // T3
  ASSERT_TRUE(r.wait_state(State::Done, 2.0)); // T5
  EXPECT_NEAR(r.position_deg(), 90.0, 0.1);
  r.release_move();
  EXPECT_EQ(r.state(), State::Ready); // T7
}

TEST(StateMachine, T3_MoveWithStopGoesStraightToDone) {
  Rig r;
  r.switch_on();
  r.pd.stop = true;
  r.start_move(90);
  r.cycle();
  EXPECT_EQ(r.state(), State::Done);
  r.run_s(0.1);
  EXPECT_NEAR(r.position_deg(), 0.0, 0.05); // did not move
}

TEST(StateMachine, T4_StopBrakesAndStaysBusyUntilStopped) {
  Rig r;
  r.switch_on();
  r.start_move(720);
  r.run_s(0.1); // cruising
  ASSERT_EQ(r.state(), State::Busy);
  r.pd.stop = true;
  r.cycle();
  EXPECT_EQ(r.state(), State::Busy); // manual 3.2 T4: Busy until stopped
  ASSERT_TRUE(r.wait_state(State::Done, 1.0));
  EXPECT_LT(r.position_deg(), 700.0); // stopped short of the target
  EXPECT_GT(r.position_deg(), 100.0);
  EXPECT_EQ(r.in.error_code, 0);
}

TEST(StateMachine, T6_SetOriginGoesDone_T7_ReleaseGoesReady) {
  Rig r;
  r.angle_rad = deg_to_rad(40.0);
  r.power_cycle();
  r.switch_on();
  EXPECT_NEAR(r.position_deg(), 40.0, 0.01);
  r.pd.set_origin = true;
  r.cycle();
  EXPECT_EQ(r.state(), State::Done);
  EXPECT_NEAR(r.position_deg(), 0.0, 0.01); // manual 4.3.2: jumps to 0, flange does not turn
  EXPECT_NEAR(rad_to_deg(r.angle_rad), 40.0, 0.05);
  r.pd.set_origin = false;
  r.cycle();
  EXPECT_EQ(r.state(), State::Ready);
}

TEST(StateMachine, T8_1_ErrorKeepingMotorOn_T10_1_ResetGoesReady) {
  Rig r;
  r.switch_on();
  r.pd.parameter_set = 9; // 114.7 code 2: motor stays on (manual 2.4 bit 1 "No")
  r.pd.move = true;
  r.cycle();
  EXPECT_EQ(r.state(), State::ErrorOn);
  EXPECT_FALSE(r.in.motor_off);
  EXPECT_EQ(r.in.error_code, 1u << 1);
  EXPECT_EQ(cause114(r, 7), 2);
  r.pd.move = false;
  r.pd.reset_error = true;
  r.cycle();
  EXPECT_EQ(r.state(), State::Ready); // T10.1
  EXPECT_EQ(r.in.error_code, 0);
  EXPECT_EQ(cause114(r, 7), 0);
}

TEST(StateMachine, T8_2_ErrorSwitchingMotorOff_T10_2_NeedsMotorOnZero) {
  Rig r;
  r.switch_on();
  r.temperature_C = 76.0; // 114.3: motor off
  r.cycle();
  r.cycle();
  EXPECT_EQ(r.state(), State::ErrorOff);
  r.temperature_C = 40.0;
  r.pd.reset_error = true; // Motor On still 1: not possible (manual 3.3)
  r.run_s(0.01);
  EXPECT_EQ(r.state(), State::ErrorOff);
  r.pd.reset_error = false;
  r.pd.motor_on = false;
  r.cycle();
  r.pd.reset_error = true;
  r.cycle();
  EXPECT_EQ(r.state(), State::MotorOff); // T10.2
  EXPECT_EQ(r.in.error_code, 0);
}

TEST(StateMachine, T9_SwitchOffInErrorOn_AndNoSwitchOnInError) {
  Rig r;
  r.switch_on();
  r.pd.parameter_set = 8;
  r.pd.move = true;
  r.cycle();
  ASSERT_EQ(r.state(), State::ErrorOn);
  r.pd.move = false;
  r.pd.motor_on = false;
  r.cycle();
  EXPECT_EQ(r.state(), State::ErrorOff); // T9
  r.pd.motor_on = true;                  // manual 3.3: switching on in error is impossible
  r.run_s(0.02);
  EXPECT_EQ(r.state(), State::ErrorOff);
}

TEST(InvalidCommands, Code1_MotorSwitchedOffInBusy_7_2) {
  Rig r;
  r.switch_on();
  r.start_move(300);
  r.run_s(0.04);
  ASSERT_EQ(r.state(), State::Busy);
  r.pd.motor_on = false;
  r.cycle();
  EXPECT_EQ(r.state(), State::ErrorOff);
  EXPECT_EQ(r.in.error_code, 1u << 2);
  EXPECT_EQ(cause114(r, 6), 1);
}

TEST(InvalidCommands, Code1_MotorSwitchedOffInDone_7_2) {
  Rig r;
  r.switch_on();
  r.pd.set_origin = true;
  r.cycle();
  ASSERT_EQ(r.state(), State::Done);
  r.pd.motor_on = false;
  r.cycle();
  EXPECT_EQ(r.state(), State::ErrorOff);
  EXPECT_EQ(cause114(r, 6), 1);
}

TEST(InvalidCommands, Code2_MoveReleasedBeforeDone_7_2) {
  Rig r;
  r.switch_on();
  r.start_move(300);
  r.run_s(0.04);
  ASSERT_EQ(r.state(), State::Busy);
  r.pd.move = false;
  r.cycle();
  EXPECT_EQ(r.state(), State::ErrorOn); // motor stays on and brakes
  EXPECT_EQ(cause114(r, 6), 2);
  r.run_s(0.3);
  const double p1 = r.position_deg();
  r.run_s(0.1);
  EXPECT_NEAR(r.position_deg(), p1, 0.05); // held still after braking
  EXPECT_LT(p1, 299.0);
}

TEST(InvalidCommands, Code4_MoveFromMotorOff_7_2) {
  Rig r;
  r.pd.move = true;
  r.cycle();
  EXPECT_EQ(r.state(), State::ErrorOff);
  EXPECT_EQ(r.in.error_code, 1u << 2);
  EXPECT_EQ(cause114(r, 6), 4);
}

// In ErrorOn a new Move is refused with code 4 as well; the motor stays on.
TEST(InvalidCommands, Code4_MoveFromErrorOn_7_2) {
  Rig r;
  r.switch_on();
  r.pd.parameter_set = 12;
  r.pd.move = true;
  r.cycle();
  ASSERT_EQ(r.state(), State::ErrorOn);
  r.pd.move = false;
  r.cycle();
  r.pd.parameter_set = 1;
  r.pd.move = true;
  r.cycle();
  EXPECT_EQ(r.state(), State::ErrorOn);
  EXPECT_EQ(cause114(r, 6), 4);
  EXPECT_EQ(cause114(r, 7), 2);
  EXPECT_EQ(r.in.error_code, (1u << 2) | (1u << 1));
}

TEST(InvalidCommands, Code5_SetOriginFromBusy_7_2) {
  Rig r;
  r.switch_on();
  r.start_move(300);
  r.run_s(0.02);
  ASSERT_EQ(r.state(), State::Busy);
  r.pd.set_origin = true; // Move still set: both set is code 6
  r.cycle();
  EXPECT_EQ(cause114(r, 6), 6);

  Rig r2; // SetOrigin from MotorOff: code 5
  r2.pd.set_origin = true;
  r2.cycle();
  EXPECT_EQ(r2.state(), State::ErrorOff);
  EXPECT_EQ(cause114(r2, 6), 5);
}

TEST(InvalidCommands, Code6_MoveAndSetOriginTogether_7_2) {
  Rig r;
  r.switch_on();
  r.pd.move = true;
  r.pd.set_origin = true;
  r.cycle();
  EXPECT_EQ(r.state(), State::ErrorOn);
  EXPECT_EQ(cause114(r, 6), 6);
  EXPECT_EQ(r.in.error_code, 1u << 2);
}

// Every row of the table carries a manual transition number or error cause.
TEST(StateMachineTable, EveryRowIsTaggedAndTransitionsCovered_3_2) {
  std::set<std::string_view> tags;
  for (const auto& t : transition_table()) {
    EXPECT_FALSE(t.tag.empty());
    tags.insert(t.tag);
  }
  for (const char* want : {"T1", "T2", "T3", "T4", "T5", "T6", "T7", "T8.1", "T8.2", "T9", "T10.1", "T10.2"}) {
    EXPECT_TRUE(tags.count(want)) << want;
  }
}

} // namespace
} // namespace sreh::test
