#include "serve/modbus_frame.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace sreh::serve::modbus {

Frame next_frame(std::span<const uint8_t> b) {
  Frame f;
  if (b.size() < 6) return f; // the length field is not in yet
  const uint16_t protocol = be16(&b[2]), length = be16(&b[4]);
  if (protocol != 0) {
    f.status = Frame::Status::Bad;
    f.why = fmt::format("protocol id {} (Modbus is 0)", protocol);
    return f;
  }
  if (length < kMinLength || length > kMaxLength) {
    f.status = Frame::Status::Bad;
    f.why = fmt::format("MBAP length {} outside {} .. {}", length, kMinLength, kMaxLength);
    return f;
  }
  const std::size_t size = 6 + static_cast<std::size_t>(length);
  if (b.size() < size) return f;
  f.status = Frame::Status::Ready;
  f.size = size;
  return f;
}

Request split(std::span<const uint8_t> frame) {
  Request r;
  r.transaction = be16(&frame[0]);
  r.unit = frame[6];
  r.pdu = frame.subspan(kMbapBytes);
  return r;
}

bool pdu_length_matches(std::span<const uint8_t> pdu) {
  if (pdu.empty()) return false;
  switch (pdu[0]) {
    case kReadHolding:
    case kWriteSingle: return pdu.size() == 5;
    case kWriteMultiple: return pdu.size() >= 6 && pdu.size() == 6u + pdu[5];
    case kReadWriteMultiple: return pdu.size() >= 10 && pdu.size() == 10u + pdu[9];
    default: return true;
  }
}

std::vector<uint8_t> answer(const Request& r, std::span<const uint8_t> pdu) {
  const std::size_t length = pdu.size() + 1;
  std::vector<uint8_t> out(kMbapBytes + pdu.size());
  out[0] = static_cast<uint8_t>(r.transaction >> 8);
  out[1] = static_cast<uint8_t>(r.transaction & 0xFF);
  out[4] = static_cast<uint8_t>(length >> 8);
  out[5] = static_cast<uint8_t>(length & 0xFF);
  out[6] = r.unit;
  std::copy(pdu.begin(), pdu.end(), out.begin() + kMbapBytes);
  return out;
}

std::vector<uint8_t> exception_answer(const Request& r, uint8_t code) {
  const uint8_t function = r.pdu.empty() ? 0x80 : static_cast<uint8_t>(r.pdu[0] | 0x80);
  const uint8_t pdu[2] = {function, code};
  return answer(r, pdu);
}

} // namespace sreh::serve::modbus
