// The Device's acyclic side: volatile diagnostics (6.4), system commands
// (6.6), LED band (3.1, index 83), firmware update (9), persistence (6.2, 6.3).
#include <gtest/gtest.h>

#include "device_logic/isdu.hpp"
#include "tests/device_logic/device_rig.hpp"

namespace sreh::test {
namespace {

TEST(VolatileDiagnostics, ErrorCausesAndWarningCausesAsRecords_6_4) {
  Rig r;
  r.switch_on();
  r.pd.parameter_set = 9;
  r.pd.move = true;
  r.cycle();
  const IsduResult all = r.dev.isdu_read(114, 0);
  ASSERT_TRUE(all.ok());
  ASSERT_EQ(all.data.size(), 8u);
  EXPECT_EQ(all.data[6], 2); // 114.7
  EXPECT_EQ(r.dev.isdu_read(115, 0).data.size(), 3u);
  EXPECT_EQ(r.dev.isdu_read(114, 9).error, kIsduSubindexNotAvailable);
  EXPECT_EQ(r.dev.isdu_read(115, 4).error, kIsduSubindexNotAvailable);
}

TEST(VolatileDiagnostics, ErrorCounterDeviceStatusDetailedStatus_6_4) {
  Rig r;
  r.cycle();
  EXPECT_EQ(r.read_u(32, 0), 0);
  EXPECT_EQ(r.read_u(36, 0), 0);
  r.temperature_C = 71;
  r.cycle();
  EXPECT_EQ(r.read_u(36, 0), 2); // warning: out of specification
  IsduResult d = r.dev.isdu_read(37, 0);
  ASSERT_EQ(d.data.size(), 12u);
  EXPECT_EQ(d.data[0], 0xE4); // warning appears (A-EVT-1)
  EXPECT_EQ((d.data[1] << 8) | d.data[2], 0x4210);
  r.temperature_C = 76;
  r.cycle();
  EXPECT_EQ(r.read_u(32, 0), 1);
  EXPECT_EQ(r.read_u(36, 0), 4); // failure
  d = r.dev.isdu_read(37, 0);
  EXPECT_EQ(d.data[0], 0xF4);
  EXPECT_EQ((d.data[1] << 8) | d.data[2], 0x4000);
  r.power_cycle();
  EXPECT_EQ(r.read_u(32, 0), 0); // errors since power-on
}

TEST(VolatileDiagnostics, TemperatureVoltageAndProcessDataImages_6_4) {
  Rig r;
  r.temperature_C = 36.5;
  r.supply_V = 23.456;
  r.pd.target_raw = 0x01020304;
  r.cycle();
  r.cycle();
  EXPECT_EQ(r.read_u(112, 0), 73);
  EXPECT_EQ(r.read_u(113, 0), 23456);
  const IsduResult out = r.dev.isdu_read(41, 0);
  ASSERT_EQ(out.data.size(), 6u);
  EXPECT_EQ(out.data[0], 0x01);
  EXPECT_EQ(out.data[3], 0x04);
  const IsduResult in = r.dev.isdu_read(40, 0);
  ASSERT_EQ(in.data.size(), 7u);
  EXPECT_EQ(in.data[6] & 1, 1); // Motor Off bit
  EXPECT_EQ(r.write_u(112, 0, 1).error, kIsduAccessDenied);
  EXPECT_EQ(r.write_u(32, 0, 1).error, kIsduAccessDenied);
}

TEST(SystemCommand, IndexTwoIsWriteOnlyAndChecksLength_6_6) {
  Rig r;
  EXPECT_EQ(r.dev.isdu_read(2, 0).error, kIsduAccessDenied);
  const std::vector<uint8_t> two{129, 0};
  EXPECT_EQ(r.dev.isdu_write(2, 0, two).error, kIsduLengthOverrun);
  EXPECT_EQ(r.dev.isdu_write(2, 0, {}).error, kIsduLengthUnderrun);
  EXPECT_EQ(r.command(200).error, kIsduFunctionUnavailable);
  EXPECT_EQ(r.command(128).error, kIsduFunctionUnavailable); // not in manual 6.6
}

TEST(SystemCommand, ApplicationReset129RestoresFactorySetup_6_6) {
  Rig r;
  ASSERT_TRUE(r.write_u(65, 1, 1234).ok());
  ASSERT_TRUE(r.write_u(83, 0, 2).ok());
  ASSERT_TRUE(r.command(129).ok());
  EXPECT_EQ(r.read_u(65, 1), 30000);
  EXPECT_EQ(r.read_u(83, 0), 1);
}

TEST(SystemCommand, BackToBox131SilentUntilPowerCycle_6_6) {
  Rig r;
  ASSERT_TRUE(r.write_u(65, 1, 1234).ok());
  r.cycle();
  ASSERT_TRUE(r.answered);
  ASSERT_TRUE(r.command(131).ok());
  r.cycle();
  EXPECT_FALSE(r.answered);
  EXPECT_NE(r.dev.isdu_read(65, 1).error, kIsduOk);
  r.power_cycle();
  r.cycle();
  EXPECT_TRUE(r.answered);
  EXPECT_EQ(r.read_u(65, 1), 30000);
}

TEST(SystemCommand, Locator126BlinksWhiteAndStopsAfter10Minutes_6_6) {
  Rig r;
  r.switch_on();
  ASSERT_TRUE(r.write_u(83, 0, 0).ok()); // regardless of the LED mode
  ASSERT_TRUE(r.command(126).ok());
  int white = 0, off = 0;
  for (int i = 0; i < 500; ++i) { // 1 s
    r.cycle();
    (r.dev.led() == LedColor::White ? white : off)++;
  }
  EXPECT_GT(white, 100);
  EXPECT_GT(off, 100);
  ASSERT_TRUE(r.command(127).ok());
  r.cycle();
  EXPECT_EQ(r.dev.led(), LedColor::Off);
  ASSERT_TRUE(r.command(126).ok());
  r.run_s(599.0);
  EXPECT_TRUE(r.dev.led() == LedColor::White || r.dev.led() == LedColor::Off);
  bool seen_white = false;
  for (int i = 0; i < 300; ++i) {
    r.cycle();
    seen_white |= r.dev.led() == LedColor::White;
  }
  EXPECT_TRUE(seen_white);
  r.run_s(1.5);
  for (int i = 0; i < 500; ++i) {
    r.cycle();
    EXPECT_EQ(r.dev.led(), LedColor::Off); // mode 0 again
  }
}

TEST(SystemCommand, ResetMaxTemperature160AndTimeAboveCritical161_6_6) {
  Rig r;
  r.temperature_C = 71;
  r.run_s(61.0);
  r.temperature_C = 30;
  r.cycle();
  EXPECT_EQ(r.read_u(98, 2), 142);
  EXPECT_EQ(r.read_u(99, 2), 142);
  EXPECT_EQ(r.read_u(100, 0), 1);
  ASSERT_TRUE(r.command(160).ok());
  r.cycle();
  EXPECT_EQ(r.read_u(99, 2), 60);  // the present 30 C
  EXPECT_EQ(r.read_u(98, 2), 142); // index 98 cannot be reset (manual 6.3)
  ASSERT_TRUE(r.command(161).ok());
  EXPECT_EQ(r.read_u(100, 0), 0);
}

TEST(PersistentDiagnostics, CountsMovesAndOperatingMinutes_6_3) {
  Rig r;
  r.switch_on();
  for (int i = 1; i <= 3; ++i) {
    ASSERT_TRUE(r.move_to_deg(30.0 * i));
    r.release_move();
  }
  EXPECT_EQ(r.read_u(96, 0), 3); // DE original: "Anzahl Drehbewegungen" (number of moves)
  r.run_s(60.0);
  EXPECT_EQ(r.read_u(97, 1), 1);
  EXPECT_EQ(r.read_u(97, 2), 1);
  EXPECT_EQ(r.read_u(97, 3), 0);
  r.power_cycle();
  EXPECT_EQ(r.read_u(96, 0), 3); // persistent
  EXPECT_EQ(r.read_u(97, 1), 1);
}

TEST(Led, ColourPerState_3_1) {
  Rig r;
  r.cycle();
  EXPECT_EQ(r.dev.led(), LedColor::Off); // Motor Off
  r.switch_on();
  EXPECT_EQ(r.dev.led(), LedColor::Green);
  r.start_move(90);
  r.cycle();
  EXPECT_EQ(r.dev.led(), LedColor::Yellow);
  ASSERT_TRUE(r.wait_state(State::Done));
  EXPECT_EQ(r.dev.led(), LedColor::Blue);
  r.pd.move = false;
  r.pd.parameter_set = 9;
  r.cycle();
  r.pd.move = true;
  r.cycle();
  EXPECT_EQ(r.dev.led(), LedColor::Red); // ErrorOn
}

TEST(Led, WarningBlinksInReadySteadyInMotorOffHiddenInError_3_1) {
  Rig r;
  r.temperature_C = 71;
  r.cycle();
  for (int i = 0; i < 50; ++i) {
    r.cycle();
    EXPECT_EQ(r.dev.led(), LedColor::Orange); // Motor Off: permanently orange
  }
  r.switch_on();
  int orange = 0, green = 0;
  for (int i = 0; i < 500; ++i) {
    r.cycle();
    (r.dev.led() == LedColor::Orange ? orange : green)++;
  }
  EXPECT_EQ(orange, 100); // 200 ms of every second
  EXPECT_EQ(green, 400);
  r.temperature_C = 76; // error: the warning is not shown
  r.cycle();
  r.cycle();
  EXPECT_EQ(r.dev.led(), LedColor::Red);
}

TEST(Led, Mode0OffMode2ErrorsAndWarningsOnly_6_2_83) {
  Rig r;
  ASSERT_TRUE(r.write_u(83, 0, 0).ok());
  r.switch_on();
  EXPECT_EQ(r.dev.led(), LedColor::Off);
  ASSERT_TRUE(r.write_u(83, 0, 2).ok());
  r.cycle();
  EXPECT_EQ(r.dev.led(), LedColor::Off); // Ready, no error
  r.temperature_C = 71;
  r.cycle();
  EXPECT_EQ(r.dev.led(), LedColor::Orange); // steady in mode 2
  r.temperature_C = 76;
  r.cycle();
  EXPECT_EQ(r.dev.led(), LedColor::Red);
}

TEST(FirmwareUpdate, BootModeViolatEndsWithGoodImage_9) {
  Rig r;
  ASSERT_TRUE(r.write_u(65, 1, 1234).ok());
  EXPECT_EQ(r.command(82).error, kIsduFunctionTempUnavailable); // not unlocked
  ASSERT_TRUE(r.command(80).ok());
  ASSERT_TRUE(r.command(81).ok());
  ASSERT_TRUE(r.command(82).ok());
  EXPECT_TRUE(r.dev.in_boot_mode());
  EXPECT_EQ(r.read_u(17343, 0), 1);
  r.pd.motor_on = true; // normal functions disabled
  r.run_s(0.02);
  EXPECT_TRUE(r.in.motor_off);
  EXPECT_EQ(r.dev.led(), LedColor::Violet); // regardless of the configuration
  EXPECT_EQ(r.dev.isdu_read(65, 1).error, kIsduServiceTempUnavailable);
  const auto good = Device::firmware_image("2.0.0");
  ASSERT_EQ(r.dev.firmware_update(good), 0);
  EXPECT_FALSE(r.dev.in_boot_mode());
  EXPECT_EQ(r.read_u(65, 1), 1234); // configuration kept
}

TEST(FirmwareUpdate, FailedUpdateStaysInBootModeAcrossPowerCycles_9) {
  Rig r;
  r.command(80);
  r.command(81);
  r.command(82);
  auto bad = Device::firmware_image("2.0.0");
  bad[6] ^= 0xFF;
  EXPECT_NE(r.dev.firmware_update(bad), 0);
  r.power_cycle();
  EXPECT_TRUE(r.dev.in_boot_mode());
  EXPECT_EQ(r.read_u(17343, 0), 2);
  const Device restored(card_drive(), r.dev.save_nvm());
  EXPECT_TRUE(restored.in_boot_mode());
  EXPECT_EQ(r.dev.firmware_update(Device::firmware_image("2.0.1")), 0);
  r.power_cycle();
  EXPECT_FALSE(r.dev.in_boot_mode());
}

// Found by the isdu fuzz target (issue 12): an End command (17344.2 = 1)
// with no chunk transferred was refused with 0x8041 yet marked the update
// failed in the non-volatile memory, so a refused write changed the device
// and the next power-on stayed in boot mode. Refused now, nothing changed
// (A-FW-4; manual 9: only an overwritten application forces boot mode).
TEST(FirmwareUpdate, EndWithoutAnyChunkIsRefusedAndChangesNothing_9) {
  Rig r;
  r.command(80);
  r.command(81);
  r.command(82);
  ASSERT_TRUE(r.dev.in_boot_mode());
  const std::vector<uint8_t> before = r.dev.save_nvm();
  const uint8_t start = 0, end = 1;
  ASSERT_TRUE(r.dev.isdu_write(Device::kFirmwareDataIndex, 2, {&start, 1}).ok());
  EXPECT_EQ(r.dev.isdu_write(Device::kFirmwareDataIndex, 2, {&end, 1}).error, kIsduInconsistentParameterSet);
  EXPECT_EQ(r.dev.isdu_write(Device::kFirmwareDataIndex, 2, {&end, 1}).error, kIsduInconsistentParameterSet);
  EXPECT_EQ(r.dev.save_nvm(), before);
  r.power_cycle();
  EXPECT_FALSE(r.dev.in_boot_mode()); // the application was never overwritten
}

TEST(Persistence, ConfigurationSurvivesPowerCycleAndMemoryImage_6_2) {
  Rig r;
  ASSERT_TRUE(r.write_u(67, 4, 5000).ok());
  ASSERT_TRUE(r.write_u(82, 0, 1).ok());
  r.power_cycle();
  EXPECT_EQ(r.read_u(67, 4), 5000);
  Device copy(card_drive(), r.dev.save_nvm());
  EXPECT_EQ(copy.isdu_read(67, 4).data, r.dev.isdu_read(67, 4).data);
  EXPECT_EQ(copy.isdu_read(82, 0).data, r.dev.isdu_read(82, 0).data);
}

// A-NVM-1: a corrupt memory image gives factory settings and error 114.1 code 1.
TEST(Persistence, CorruptMemoryImageIsDeviceError_7_2_114_1) {
  Rig r;
  auto image = r.dev.save_nvm();
  image[image.size() / 2] ^= 0x5A;
  Device d(card_drive(), image);
  const auto in = decode_in(*d.exchange(encode(ProcessDataOut{})));
  EXPECT_EQ(in.error_code, 1u << 7);
  EXPECT_EQ(d.isdu_read(114, 1).data, std::vector<uint8_t>{1});
}

TEST(Persistence, SameInputsGiveSameOutputsBitForBit) {
  auto run = [] {
    Rig r;
    r.switch_on();
    r.move_to_deg(123.4);
    return std::make_pair(r.angle_rad, r.in.position_raw);
  };
  EXPECT_EQ(run(), run());
}

} // namespace
} // namespace sreh::test
