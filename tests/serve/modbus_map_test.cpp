// The Modbus register map (docs/modbus-map.md): process data octets
// big-endian in registers as the manual's bytes (manual 2.2, 2.3), the ISDU
// channel, writable ranges, and a layout that does not depend on --ports.
#include <gtest/gtest.h>

#include "serve/modbus_map.hpp"

namespace sreh::serve::modbus {
namespace {

struct ModbusMap : ::testing::Test {
  Hub hub{std::vector<TwinConfig>(2), HubOptions{}};
  std::vector<uint16_t> block = std::vector<uint16_t>(kPortBlock, 0);
  PortRegisters regs;
  EventTracker events;
  Hub::Port& port = hub.port(1);

  void write(int offset, std::vector<uint16_t> values) {
    ASSERT_EQ(check_write(offset, values, block.data()), "");
    fill_port(block.data(), port, regs, events);
    std::copy(values.begin(), values.end(), block.begin() + offset);
    apply_write(block.data(), offset, static_cast<int>(values.size()), port, regs);
  }
};

TEST_F(ModbusMap, ProcessDataOutOctetsBigEndian_2_2) {
  write(kPdOut, {0x0000, 0x4000, 0x0101}); // target 90 deg, set 1, motor on
  EXPECT_EQ(port.twin.pd_out().target_raw, 16384);
  EXPECT_EQ(port.twin.pd_out().parameter_set, 1);
  EXPECT_TRUE(port.twin.pd_out().motor_on);
  write(kPdOut + 2, {0x0100}); // one register alone: the rest of the frame stays
  EXPECT_EQ(port.twin.pd_out().target_raw, 16384);
  EXPECT_FALSE(port.twin.pd_out().motor_on);
}

TEST_F(ModbusMap, ProcessDataInAfterCycles_2_3) {
  write(kPdOut, {0, 0, 0x0001});
  for (int i = 0; i < 50; ++i) hub.step_all();
  fill_port(block.data(), port, regs, events);
  // 7 octets: position (4), error code, warning code, status bits; Ready = bit 1
  EXPECT_EQ(block[kPdIn + 3], 0x0200);
  EXPECT_EQ(block[kState], 1); // Ready
  EXPECT_EQ(block[kStatus] & 3, 3);
}

TEST_F(ModbusMap, IsduChannelReadAndRefusedWrite) {
  write(kIsduCommand, {1, 64, 1, 0});
  EXPECT_EQ(block[kRespSequence], 1);
  EXPECT_EQ(block[kRespStatus], 1);
  EXPECT_EQ(block[kRespLength], 2);
  EXPECT_EQ(block[kRespData], 0x012C); // 300
  write(kIsduCommand, {2, 64, 1, 2, 0xC350}); // 50000: out of range
  EXPECT_EQ(block[kRespSequence], 2);
  EXPECT_EQ(block[kRespStatus], 2);
  EXPECT_EQ(block[kRespError], 0x8030);
  EXPECT_EQ(port.twin.isdu_read(64, 1).data, (std::vector<uint8_t>{0x01, 0x2C}));
}

TEST_F(ModbusMap, WritableRangesOnly) {
  EXPECT_TRUE(writable(kPdOut, 4));
  EXPECT_FALSE(writable(kPdIn, 1));
  EXPECT_FALSE(writable(kPdOut, 5));
  EXPECT_FALSE(writable(kRespSequence, 1));
  EXPECT_TRUE(writable(kIsduCommand, kIsduRequestCount));
  EXPECT_NE(check_write(kPdOutValid, {2}, block.data()), "");
  EXPECT_NE(check_write(kIsduCommand, {3}, block.data()), "");
  EXPECT_NE(check_write(kIsduCommand, {2, 64, 1, 233}, block.data()), "");
}

TEST_F(ModbusMap, PortOneLayoutDoesNotDependOnPortCount) {
  EXPECT_EQ(map_json(1)["ports"][0], map_json(8)["ports"][0]);
  EXPECT_EQ(map_json(1)["ports"][0]["pd_in"]["register"], 1001);
  EXPECT_EQ(map_json(8)["ports"].size(), 8u);
}

} // namespace
} // namespace sreh::serve::modbus
