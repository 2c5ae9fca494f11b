// Issue 15 on the twin: rig settings mid-run, power off with the flange
// turned by hand, start-up after power-on, firmware transfer over time.
#include <gtest/gtest.h>

#include <stdexcept>

#include "device_logic/units.hpp"
#include "twin/firmware_transfer.hpp"
#include "twin/plant.hpp"
#include "twin/twin.hpp"

namespace sreh {
namespace {

TEST(TwinConformance, MasterCycleSetsStepRefusesBad_1_A_LINK_2) {
  Twin twin(TwinConfig{});
  twin.run_cycle();
  EXPECT_NEAR(twin.time_s(), 0.002, 1e-12);
  EXPECT_THROW(twin.set_master_cycle_s(0.001), std::invalid_argument);   // manual 1: 2 ms minimum
  EXPECT_THROW(twin.set_master_cycle_s(0.00225), std::invalid_argument); // not whole physics steps
  EXPECT_THROW(twin.set_master_cycle_s(0.2), std::invalid_argument);     // beyond MasterCycleTime
  EXPECT_DOUBLE_EQ(twin.master_cycle_s(), 0.002);                        // unchanged
  twin.set_master_cycle_s(0.032);
  twin.run_cycle();
  EXPECT_NEAR(twin.time_s(), 0.034, 1e-12);
  EXPECT_EQ(twin.cycles(), 2u);
}

TEST(TwinConformance, TurnedWhileOffReadsTheFourRevolutionRule_4_1) {
  Twin twin(TwinConfig{});
  twin.run_cycle();
  twin.power_off_for(0.5, 1080.0);
  EXPECT_NEAR(rad_to_deg(twin.plant().angle_rad()), 1080.0, 1e-9); // the flange really turned
  EXPECT_EQ(twin.iolink_led(), IoLinkLedMode::Startup);
  for (int i = 0; i < 3; ++i) twin.run_cycle();
  EXPECT_EQ(twin.iolink_led(), IoLinkLedMode::Operate);
  EXPECT_NEAR(wire_counts_to_deg(twin.pd_in().position_raw), -360.0, 0.01);
  EXPECT_NEAR(twin.time_s(), 0.002 + 0.5 + 0.006, 1e-9);
}

TEST(TwinConformance, TurnIsSpreadOverTheOffTime_4_1) {
  Twin twin(TwinConfig{});
  twin.power_off();
  twin.turn_flange(90.0, 0.1); // 50 cycles
  for (int i = 0; i < 25; ++i) twin.run_cycle();
  const double half = rad_to_deg(twin.plant().angle_rad());
  EXPECT_GT(half, 30.0);
  EXPECT_LT(half, 60.0);
  for (int i = 0; i < 25; ++i) twin.run_cycle();
  EXPECT_NEAR(rad_to_deg(twin.plant().angle_rad()), 90.0, 1e-9);
}

TEST(TwinConformance, PdResumesOnlyInOperateAfterPowerOn_A_LINK_3) {
  Twin twin(TwinConfig{});
  ProcessDataOut pd;
  pd.motor_on = true;
  twin.set_pd_out(pd);
  twin.run_cycle();
  ASSERT_TRUE(twin.pd_in().ready);
  pd.motor_on = false;
  twin.set_pd_out(pd);
  twin.run_cycle();
  twin.power_cycle();
  pd.motor_on = true;
  twin.set_pd_out(pd);
  twin.run_cycle(); // STARTUP
  twin.run_cycle(); // PREOPERATE
  EXPECT_EQ(twin.iolink_led(), IoLinkLedMode::Preoperate);
  EXPECT_EQ(twin.telemetry().state, State::MotorOff); // no process data yet
  twin.run_cycle(); // OPERATE: Motor On arrives
  EXPECT_EQ(twin.iolink_led(), IoLinkLedMode::Operate);
  EXPECT_TRUE(twin.pd_in().ready);
}

TEST(TwinConformance, AmbientChangeHeatsTheModule) {
  TwinConfig c;
  c.thermal.time_scale = 2000;
  Twin twin(c);
  twin.set_ambient_C(60.0);
  for (int i = 0; i < 1000; ++i) twin.run_cycle(); // 2 s, x2000: 67 min, twice the housing's time constant
  EXPECT_GT(twin.telemetry().temperature_C, 50.0);
  EXPECT_LT(twin.telemetry().temperature_C, 60.0 + 1e-9);
}

TEST(TwinConformance, FirmwareTransferTakesItsWireTime_9_A_FW_5) {
  EXPECT_EQ(isdu_write_cycles(232), 120u);
  EXPECT_EQ(isdu_write_cycles(1), 5u);
  // A 256 KiB image at the 2 ms minimum cycle: "several minutes" (manual 9).
  const std::vector<uint8_t> image = Device::firmware_image("2.0.0", 256 * 1024);
  uint64_t cycles = 0;
  for (const IsduWriteRequest& w : firmware_requests(image)) cycles += isdu_write_cycles(w.data.size());
  const double minutes = static_cast<double>(cycles) * 0.002 / 60.0;
  EXPECT_GT(minutes, 2.0);
  EXPECT_LT(minutes, 10.0);
  // A small image through the twin: time passes, the module restarts normally.
  Twin twin(TwinConfig{});
  for (const uint8_t cmd : std::vector<uint8_t>{80, 81, 82}) ASSERT_TRUE(twin.isdu_write(2, 0, std::vector<uint8_t>{cmd}).ok());
  const std::vector<uint8_t> small = Device::firmware_image("2.0.0", 1024);
  ASSERT_EQ(twin.firmware_update(small), 0);
  uint64_t want = 0;
  for (const IsduWriteRequest& w : firmware_requests(small)) want += isdu_write_cycles(w.data.size());
  EXPECT_EQ(twin.cycles(), want);
  EXPECT_FALSE(twin.device().in_boot_mode());
  EXPECT_EQ(twin.iolink_led(), IoLinkLedMode::Startup); // restarted
}

} // namespace
} // namespace sreh
