// Position measurement, manual chapter 4: the device position in the PLC's
// frame is  user = dir * encoder - origin  (internal counts, 2^19 per rev),
// where dir is the configured positive direction (index 82, manual 4.2) and
// origin the active zero point. The zero offset (index 86) is applied in the
// PLC's frame, which is why the manual (4.2) warns that changing the direction
// after setting the zero point shifts it.
#pragma once
#include <cstdint>

#include "device_logic/units.hpp"

namespace sreh {

inline constexpr int64_t kMultiturnRevs = 4; // manual 4.1: 4-fold multiturn
inline constexpr int64_t kMultiturnSpan = kMultiturnRevs * kInternalCountsPerRev;
inline constexpr int64_t kHalfMultiturnSpan = kMultiturnSpan / 2; // 720 deg

constexpr int64_t floor_div(int64_t a, int64_t b) {
  const int64_t q = a / b;
  return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}
constexpr int64_t floor_mod(int64_t a, int64_t b) { return a - floor_div(a, b) * b; }

// Manual 4.3.3: initialising the zero point adds a multiple of 4 revolutions
// to the stored offset so that the actual position lies in [-720, +720) deg
// (A-POS-1: the upper end is open). Only the encoder value modulo 4
// revolutions matters, as for the real 4-turn absolute encoder (manual 4.1).
constexpr int64_t initial_origin(int64_t encoder_counts, int dir, int64_t zero_offset_wire) {
  const int64_t base = zero_offset_wire * kInternalPerWireCount;
  const int64_t user = dir * encoder_counts - base;
  const int64_t n = floor_div(user + kHalfMultiturnSpan, kMultiturnSpan);
  return base + n * kMultiturnSpan;
}

constexpr int64_t user_position(int64_t encoder_counts, int dir, int64_t origin) {
  return dir * encoder_counts - origin;
}
// The inverse: the physical encoder position of a user position.
constexpr int64_t physical_position(int64_t user_counts, int dir, int64_t origin) {
  return dir * (user_counts + origin);
}

// Process data position: 2^16 counts per revolution, floored, wrapped to
// int32 beyond +-2^15 revolutions (manual 2.5).
constexpr int64_t user_to_wire(int64_t user_counts) { return floor_div(user_counts, kInternalPerWireCount); }

// Store Origin (manual 6.6 cmd 171): the active origin, reduced by whole
// multiples of 4 revolutions into the range of index 86 (+-720 deg), in wire counts.
constexpr int64_t origin_to_zero_offset_wire(int64_t origin) {
  const int64_t reduced = floor_mod(origin + kHalfMultiturnSpan, kMultiturnSpan) - kHalfMultiturnSpan;
  return floor_div(reduced + kInternalPerWireCount / 2, kInternalPerWireCount);
}

// Shortest path (manual 3.4): only the low 16 bits of the target count; the
// whole revolutions are chosen so the travel is at most 180 deg. Exactly 180
// deg goes in the positive direction (A-POS-2).
constexpr int64_t shortest_path_target(int64_t actual_user, int32_t target_wire) {
  const int64_t angle = int64_t{static_cast<uint16_t>(static_cast<uint32_t>(target_wire) & 0xFFFFu)} * kInternalPerWireCount;
  int64_t d = floor_mod(angle - actual_user, kInternalCountsPerRev);
  if (d > kInternalCountsPerRev / 2) d -= kInternalCountsPerRev;
  return actual_user + d;
}

} // namespace sreh
