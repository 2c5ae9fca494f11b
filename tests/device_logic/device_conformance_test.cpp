// Issue 15: link watchdog at the master's cycle time, the IO-Link status LED
// through start-up, and the firmware transfer in ISDU chunks (manual 1, 5, 9).
#include <gtest/gtest.h>

#include "device_rig.hpp"

namespace sreh::test {
namespace {

// Exchanges every `cycle_steps` control steps, `cycles` times, with the link
// silent for the cycles in [lost_from, lost_to).
void run_cycles(Rig& r, int cycle_steps, int cycles, int lost_from = -1, int lost_to = -1) {
  for (int c = 0; c < cycles; ++c) {
    if (c < lost_from || c >= lost_to) {
      const auto f = r.dev.exchange(encode(r.pd), true);
      if (f) r.in = decode_in(*f);
    }
    for (int i = 0; i < cycle_steps; ++i) r.step();
  }
}

constexpr int k32ms = 320; // 32 ms in 0.1 ms control steps

TEST(LinkWatchdog, SlowRegularCycleIsNoInterruption_A_LINK_1) {
  Rig r;
  r.dev.set_master_cycle_time(0.032);
  r.pd.motor_on = true;
  run_cycles(r, k32ms, 40);
  EXPECT_EQ(r.state(), State::Ready);
  EXPECT_EQ(r.read_u(114, 6), 0);
}

TEST(LinkWatchdog, Unannounced32msMasterTripsAfter20ms_A_LINK_1) {
  Rig r; // the master never announced its cycle: 2 ms assumed, watchdog 20 ms
  r.pd.motor_on = true;
  run_cycles(r, 20, 5);
  run_cycles(r, k32ms, 3);
  EXPECT_EQ(r.read_u(114, 6), 16);
}

TEST(LinkWatchdog, ThreeMasterCyclesOfSilenceAreTheLimit_5_A_LINK_1) {
  Rig r;
  r.dev.set_master_cycle_time(0.032);
  r.pd.motor_on = true;
  run_cycles(r, k32ms, 5);
  run_cycles(r, k32ms, 4, 1, 3); // 2 cycles lost: silent 96 ms, not longer than 3 cycles
  EXPECT_EQ(r.read_u(114, 6), 0);
  run_cycles(r, k32ms, 6, 1, 4); // 3 lost: silent 128 ms
  EXPECT_EQ(r.read_u(114, 6), 16);
  EXPECT_EQ(r.state(), State::ErrorOff);
}

TEST(LinkWatchdog, TwentyMsFloorAtFastCycles_A_LINK_1) {
  Rig r;
  r.dev.set_master_cycle_time(0.002);
  r.pd.motor_on = true;
  r.run_s(0.02);
  r.link_up = false;
  for (int i = 0; i < 180; ++i) r.step(); // with the 2 ms after the last exchange: silent for 20 ms
  EXPECT_EQ(r.read_u(114, 6), 0);
  r.step();                                // longer than 20 ms

  EXPECT_EQ(r.read_u(114, 6), 16);
}

TEST(IoLinkLed, OperateWithOutputsInvalid_1_and_5) {
  Rig r;
  r.cycle();
  EXPECT_EQ(r.dev.io_link_led(), IoLinkLedMode::Operate);
  r.outputs_valid = false; // DeviceOperate
  r.run_s(0.01);
  EXPECT_EQ(r.dev.io_link_led(), IoLinkLedMode::Operate);
}

TEST(IoLinkLed, StartupAfterEveryPowerOnThenPreoperateThenOperate_1) {
  Rig r;
  r.run_s(0.01);
  for (int n = 0; n < 2; ++n) {
    r.dev.power_off();
    EXPECT_EQ(r.dev.io_link_led(), IoLinkLedMode::NotConnected);
    r.dev.power_on(r.sensors());
    EXPECT_EQ(r.dev.io_link_led(), IoLinkLedMode::Startup);
    ASSERT_TRUE(r.dev.startup_cycle(ComPhase::Startup));
    EXPECT_EQ(r.dev.io_link_led(), IoLinkLedMode::Startup);
    ASSERT_TRUE(r.dev.startup_cycle(ComPhase::Preoperate));
    EXPECT_EQ(r.dev.io_link_led(), IoLinkLedMode::Preoperate);
    r.cycle();
    EXPECT_EQ(r.dev.io_link_led(), IoLinkLedMode::Operate);
  }
}

TEST(IoLinkLed, OffWhenTheLinkIsLost_1) {
  Rig r;
  r.run_s(0.01);
  r.link_up = false;
  r.run_s(0.03);
  EXPECT_EQ(r.dev.io_link_led(), IoLinkLedMode::NotConnected);
}

void enter_boot_mode(Rig& r) {
  ASSERT_TRUE(r.command(80).ok());
  ASSERT_TRUE(r.command(81).ok());
  ASSERT_TRUE(r.command(82).ok());
  ASSERT_TRUE(r.dev.in_boot_mode());
}

IsduResult chunk(Rig& r, std::span<const uint8_t> data) { return r.dev.isdu_write(Device::kFirmwareDataIndex, 1, data); }
IsduResult fw_command(Rig& r, uint8_t c) { return r.dev.isdu_write(Device::kFirmwareDataIndex, 2, std::vector<uint8_t>{c}); }

TEST(FirmwareTransfer, ChunksOnlyInBootMode_9_A_FW_4) {
  Rig r;
  const std::vector<uint8_t> data(10, 0x55);
  EXPECT_EQ(chunk(r, data).error, kIsduServiceTempUnavailable);
  EXPECT_EQ(r.dev.isdu_read(Device::kFirmwareDataIndex, 1).error, kIsduAccessDenied);
  enter_boot_mode(r);
  EXPECT_EQ(chunk(r, std::vector<uint8_t>(233, 0)).error, kIsduLengthOverrun);
  EXPECT_EQ(chunk(r, std::vector<uint8_t>{}).error, kIsduLengthUnderrun);
  EXPECT_EQ(fw_command(r, 7).error, kIsduValueOutOfRange);
  EXPECT_EQ(r.dev.isdu_write(Device::kFirmwareDataIndex, 3, data).error, kIsduSubindexNotAvailable);
}

TEST(FirmwareTransfer, PowerLossMidTransferLeavesBootMode_9) {
  Rig r;
  ASSERT_TRUE(r.write_u(65, 1, 12345).ok());
  enter_boot_mode(r);
  const std::vector<uint8_t> image = Device::firmware_image("2.0.0", 4096);
  ASSERT_EQ(image.size(), 4096u);
  ASSERT_TRUE(fw_command(r, 0).ok());
  ASSERT_TRUE(chunk(r, std::span(image).first(232)).ok());
  EXPECT_EQ(r.read_u(17343, 0), 1); // transfer running: boot mode
  r.power_cycle();
  EXPECT_TRUE(r.dev.in_boot_mode());
  EXPECT_EQ(r.read_u(17343, 0), 2); // boot mode after a failed update (A-FW-1)
  // The retry, whole, in chunks.
  ASSERT_TRUE(fw_command(r, 0).ok());
  for (std::size_t at = 0; at < image.size(); at += 232) {
    ASSERT_TRUE(chunk(r, std::span(image).subspan(at, std::min<std::size_t>(232, image.size() - at))).ok());
  }
  ASSERT_TRUE(fw_command(r, 1).ok());
  EXPECT_FALSE(r.dev.in_boot_mode());
  EXPECT_EQ(r.read_u(17343, 0), 0);
  EXPECT_EQ(r.read_u(65, 1), 12345); // configuration kept (manual 9)
}

TEST(FirmwareTransfer, PowerLossBeforeAnyChunkKeepsTheApplication_9) {
  Rig r;
  enter_boot_mode(r);
  ASSERT_TRUE(fw_command(r, 0).ok());
  r.power_cycle();
  EXPECT_FALSE(r.dev.in_boot_mode());
}

TEST(FirmwareTransfer, CorruptImageFailsWith8041_9_A_FW_3) {
  Rig r;
  enter_boot_mode(r);
  std::vector<uint8_t> image = Device::firmware_image("2.0.0", 1000);
  image[500] ^= 0x01;
  EXPECT_EQ(r.dev.firmware_update(image), kIsduInconsistentParameterSet);
  EXPECT_EQ(r.read_u(17343, 0), 2);
  image[500] ^= 0x01;
  EXPECT_EQ(r.dev.firmware_update(image), 0);
  EXPECT_FALSE(r.dev.in_boot_mode());
}

TEST(FirmwareTransfer, PaddedImageKeepsItsVersionAndSize_A_FW_3) {
  const std::vector<uint8_t> small = Device::firmware_image("1.2.0");
  EXPECT_EQ(small.size(), 5u + 5u + 4u);
  const std::vector<uint8_t> big = Device::firmware_image("1.2.0", 256 * 1024);
  EXPECT_EQ(big.size(), 256u * 1024u);
  EXPECT_TRUE(std::equal(small.begin(), small.begin() + 10, big.begin()));
  EXPECT_EQ(big[10], 0); // end of the version text
}

} // namespace
} // namespace sreh::test
