// Fault injection shared by `serve` and the Python API (issue 18): a blocked
// flange is a MuJoCo constraint, ambient temperature a thermal boundary. The
// device only sees the consequences through its sensors.
#include <gtest/gtest.h>

#include <cmath>

#include "device_logic/units.hpp"
#include "twin/plant.hpp"
#include "twin/twin.hpp"

namespace sreh {
namespace {

TwinConfig config_2000() {
  TwinConfig c;
  c.load = InertiaLoad{2000};
  c.record_trace = false;
  return c;
}

void configure_load(Twin& twin) { // parameter set 1: configured load = actual load (manual 6.2, 65.4)
  const uint8_t bytes[2] = {2000 >> 8, 2000 & 0xFF};
  ASSERT_TRUE(twin.isdu_write(65, 4, bytes).ok());
}

void motor_on(Twin& twin, ProcessDataOut& pd) {
  configure_load(twin);
  pd.motor_on = true;
  twin.set_pd_out(pd);
  for (int i = 0; i < 100 && !twin.pd_in().ready; ++i) twin.run_cycle();
  ASSERT_TRUE(twin.pd_in().ready);
}

// A jammed flange does not move although the device commands a move and the
// motor pushes: the device sees the setpoint run away from the encoder and
// trips its tracking-error monitor (manual 2.4 bit 3, 114.5), from physics.
TEST(FaultInjection, BlockedFlangeHoldsAndTripsTrackingError_2_4) {
  Twin twin(config_2000());
  ProcessDataOut pd;
  motor_on(twin, pd);
  twin.set_flange_blocked(true);
  EXPECT_TRUE(twin.flange_blocked());
  const double start_deg = twin.telemetry().position_deg;
  pd.target_raw = static_cast<int32_t>(deg_to_wire_counts(90));
  pd.parameter_set = 1;
  pd.move = true;
  twin.set_pd_out(pd);
  double max_torque = 0;
  for (int i = 0; i < 100; ++i) { // 0.2 s
    twin.run_cycle();
    max_torque = std::max(max_torque, std::abs(twin.plant().applied_torque_Nm()));
  }
  EXPECT_NEAR(twin.telemetry().position_deg, start_deg, 0.05);
  EXPECT_NEAR(rad_to_deg(twin.plant().angle_rad()), 0.0, 0.05);
  EXPECT_GT(max_torque, 0.1); // the motor did push against the constraint
  EXPECT_TRUE(twin.pd_in().error);
  EXPECT_EQ(twin.pd_in().error_code & 0x08, 0x08); // tracking error
}

// The same move without the fault completes: the error above is the jam's.
TEST(FaultInjection, SameMoveUnblockedCompletes) {
  Twin twin(config_2000());
  ProcessDataOut pd;
  motor_on(twin, pd);
  pd.target_raw = static_cast<int32_t>(deg_to_wire_counts(90));
  pd.parameter_set = 1;
  pd.move = true;
  twin.set_pd_out(pd);
  for (int i = 0; i < 1000 && !twin.pd_in().done; ++i) twin.run_cycle();
  EXPECT_TRUE(twin.pd_in().done);
  EXPECT_EQ(twin.pd_in().error_code, 0);
}

TEST(FaultInjection, FreedFlangeMovesAgain) {
  Twin twin(config_2000());
  ProcessDataOut pd;
  motor_on(twin, pd);
  twin.set_flange_blocked(true);
  for (int i = 0; i < 50; ++i) twin.run_cycle();
  twin.set_flange_blocked(false);
  EXPECT_FALSE(twin.flange_blocked());
  pd.target_raw = static_cast<int32_t>(deg_to_wire_counts(90));
  pd.parameter_set = 1;
  pd.move = true;
  twin.set_pd_out(pd);
  for (int i = 0; i < 1000 && !twin.pd_in().done; ++i) twin.run_cycle();
  EXPECT_TRUE(twin.pd_in().done);
  EXPECT_NEAR(twin.telemetry().position_deg, 90.0, 0.2);
}

// A flange jammed while it moves, with no load (the lightest flange side,
// where the mesh damping's h d is 1.7 x its inertia): the jam stops it where
// it was, the tracking error switches the motor off, and the numbers stay
// finite whatever the moment (A-TWIN-47; before, 58 of 60 moments blew up).
// Fourteen moments, 2 ms apart, cover the backlash and cogging phases.
TEST(FaultInjection, FlangeJammedWhileMovingStopsThere_2_4) {
  for (int cycles = 2; cycles < 30; cycles += 2) {
    SCOPED_TRACE("jammed after " + std::to_string(cycles) + " cycles");
    TwinConfig c;
    c.record_trace = false;
    Twin twin(c);
    const uint8_t speed[2] = {2000 >> 8, 2000 & 0xFF}; // 200 deg/s (manual 6.2, 65.1)
    ASSERT_TRUE(twin.isdu_write(65, 1, speed).ok());
    ProcessDataOut pd;
    pd.motor_on = true;
    twin.set_pd_out(pd);
    for (int i = 0; i < 100 && !twin.pd_in().ready; ++i) twin.run_cycle();
    pd.target_raw = static_cast<int32_t>(deg_to_wire_counts(-45));
    pd.parameter_set = 1;
    pd.move = true;
    twin.set_pd_out(pd);
    for (int i = 0; i < cycles; ++i) twin.run_cycle();
    ASSERT_GT(std::abs(twin.plant().velocity_rad_s()), 0.1); // moving
    twin.set_flange_blocked(true);
    const double jammed_deg = rad_to_deg(twin.plant().angle_rad());
    for (int i = 0; i < 200; ++i) { // 0.4 s: error, motor off, at rest
      twin.run_cycle();
      ASSERT_NEAR(rad_to_deg(twin.plant().angle_rad()), jammed_deg, 0.1) << "cycle " << i;
    }
    EXPECT_TRUE(twin.pd_in().error);
    EXPECT_EQ(twin.pd_in().error_code & 0x08, 0x08); // tracking error (manual 7.2, 114.5)
  }
}

// A hotter room heats the module towards it (index 112 follows).
TEST(FaultInjection, AmbientTemperatureDrivesModuleTemperature) {
  TwinConfig c = config_2000();
  c.thermal.time_scale = 1000; // documented accelerator, so seconds of sim time suffice
  Twin twin(c);
  twin.set_ambient_C(60.0);
  for (int i = 0; i < 2500; ++i) twin.run_cycle(); // 5 s x 1000
  EXPECT_GT(twin.telemetry().temperature_C, 50.0);
  EXPECT_THROW(twin.set_ambient_C(NAN), std::invalid_argument);
}

} // namespace
} // namespace sreh
