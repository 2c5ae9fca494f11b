// Modbus TCP framing (issue 27), without I/O so it can be fuzzed: the MBAP
// header (transaction id, protocol id, length, unit id) is checked before a
// frame is taken, every PDU of a supported function must be exactly as long
// as its fields say, and exceptions carry function | 0x80.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sreh::serve::modbus {

inline constexpr std::size_t kMbapBytes = 7;     // transaction, protocol, length, unit
inline constexpr std::size_t kMinLength = 2;     // unit id + function code
inline constexpr std::size_t kMaxLength = 254;   // unit id + the largest PDU (253 octets)

inline constexpr uint8_t kReadHolding = 3;
inline constexpr uint8_t kWriteSingle = 6;
inline constexpr uint8_t kWriteMultiple = 16;
inline constexpr uint8_t kReadWriteMultiple = 23;

inline constexpr uint8_t kIllegalFunction = 1;
inline constexpr uint8_t kIllegalAddress = 2;
inline constexpr uint8_t kIllegalValue = 3;

struct Frame {
  enum class Status { NeedMore, Ready, Bad };
  Status status = Status::NeedMore;
  std::size_t size = 0;  // Ready: octets of the whole frame (header included)
  std::string why;       // Bad: what was wrong (closes the connection)
};

// Looks at the start of `buffer`: a complete frame, more octets needed, or a
// header no Modbus TCP client sends (protocol id not 0, length outside 2 .. 254).
Frame next_frame(std::span<const uint8_t> buffer);

struct Request {
  uint16_t transaction = 0;
  uint8_t unit = 0;
  std::span<const uint8_t> pdu; // function code first
};
// Splits a Ready frame.
Request split(std::span<const uint8_t> frame);

// For FC 3, 6, 16, 23: whether the PDU is exactly as long as its fields say
// (a mismatch closes the connection); other functions: true (answered 01).
bool pdu_length_matches(std::span<const uint8_t> pdu);

// The ADU of an answer: MBAP header (same transaction and unit) + pdu.
std::vector<uint8_t> answer(const Request& request, std::span<const uint8_t> pdu);
std::vector<uint8_t> exception_answer(const Request& request, uint8_t code);

inline uint16_t be16(const uint8_t* p) { return static_cast<uint16_t>((p[0] << 8) | p[1]); }

} // namespace sreh::serve::modbus
