// Helpers the twin tests share (twin_physics_test.cpp, drive_clock_test.cpp).
#pragma once
#include <gtest/gtest.h>

#include <cstdint>

#include "twin/twin.hpp"

namespace sreh::test {

// A uint16 parameter written as a PLC would (big-endian, manual 6.2); the
// write must be accepted.
inline void write_raw(Twin& twin, uint16_t index, uint8_t sub, uint16_t value) {
  const uint8_t bytes[2] = {static_cast<uint8_t>(value >> 8), static_cast<uint8_t>(value & 0xFF)};
  ASSERT_TRUE(twin.isdu_write(index, sub, bytes).ok()) << index << "." << int{sub};
}

} // namespace sreh::test
