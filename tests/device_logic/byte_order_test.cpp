// Big-endian helpers: IO-Link sends the most significant octet first
// (manual 2.2/2.3 position bytes, ISDU numbers, Data Storage index lists).
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "device_logic/byte_order.hpp"

namespace sreh {
namespace {

TEST(ByteOrder, MostSignificantOctetFirst) {
  std::vector<uint8_t> out;
  be::append16(out, 0x1234);
  be::append32(out, 0xDEADBEEF);
  EXPECT_EQ(out, (std::vector<uint8_t>{0x12, 0x34, 0xDE, 0xAD, 0xBE, 0xEF}));
  EXPECT_EQ(be::read16(out), 0x1234);
  EXPECT_EQ(be::read32(out, 2), 0xDEADBEEFu);
  EXPECT_EQ(be::read(std::span<const uint8_t>(out).first(3)), 0x1234DEu);
}

TEST(ByteOrder, WriteKeepsTheLowOctets) {
  std::array<uint8_t, 2> two{};
  be::write(two, 0xABCDEF);
  EXPECT_EQ(two, (std::array<uint8_t, 2>{0xCD, 0xEF}));
}

} // namespace
} // namespace sreh
