// Big-endian (network) byte order, as IO-Link sends every multi-octet value
// (process data, ISDU, Data Storage lists, the memory image). The one place
// the shifts are written (issue 13).
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace sreh::be {

// Unsigned value of the first `bytes.size()` (at most 8) octets, most significant first.
constexpr uint64_t read(std::span<const uint8_t> bytes) {
  uint64_t v = 0;
  for (uint8_t b : bytes) v = (v << 8) | b;
  return v;
}
constexpr uint16_t read16(std::span<const uint8_t> b, std::size_t at = 0) {
  return static_cast<uint16_t>(read(b.subspan(at, 2)));
}
constexpr uint32_t read32(std::span<const uint8_t> b, std::size_t at = 0) {
  return static_cast<uint32_t>(read(b.subspan(at, 4)));
}

// Writes the low `out.size()` octets of `v`, most significant first.
constexpr void write(std::span<uint8_t> out, uint64_t v) {
  for (std::size_t i = out.size(); i-- > 0; v >>= 8) out[i] = static_cast<uint8_t>(v);
}
inline void append(std::vector<uint8_t>& out, uint64_t v, std::size_t octets) {
  out.resize(out.size() + octets);
  write(std::span<uint8_t>(out).last(octets), v);
}
inline void append16(std::vector<uint8_t>& out, uint16_t v) { append(out, v, 2); }
inline void append32(std::vector<uint8_t>& out, uint32_t v) { append(out, v, 4); }

} // namespace sreh::be
