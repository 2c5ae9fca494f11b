#include "device_logic/process_data.hpp"
#include "device_logic/byte_order.hpp"

#include <stdexcept>
#include <string>

namespace sreh {
namespace {

void put_be32(uint8_t* p, int32_t v) { be::write(std::span<uint8_t>(p, 4), static_cast<uint32_t>(v)); }
int32_t get_be32(const uint8_t* p) { return static_cast<int32_t>(be::read32(std::span<const uint8_t>(p, 4))); }

constexpr bool bit(uint8_t byte, int n) { return ((byte >> n) & 1u) != 0; }
constexpr uint8_t flag(bool b, int n) { return static_cast<uint8_t>(b ? (1u << n) : 0u); }

void check_length(std::size_t got, std::size_t want, const char* what) {
  if (got != want) {
    throw std::invalid_argument(std::string(what) + " frame must be " + std::to_string(want) +
                                " bytes, got " + std::to_string(got));
  }
}

} // namespace

// Byte 0 carries bits 47..40 (big-endian), byte 5 bits 7..0 (manual 2.2).
PdOutFrame encode(const ProcessDataOut& pd) {
  PdOutFrame f{};
  put_be32(&f[0], pd.target_raw);
  f[4] = pd.parameter_set;
  f[5] = static_cast<uint8_t>(flag(pd.shortest_path, 6) | flag(pd.relative, 5) | flag(pd.set_origin, 4) |
                              flag(pd.reset_error, 3) | flag(pd.stop, 2) | flag(pd.move, 1) |
                              flag(pd.motor_on, 0));
  return f;
}

ProcessDataOut decode_out(const PdOutFrame& f) {
  ProcessDataOut pd;
  pd.target_raw = get_be32(&f[0]);
  pd.parameter_set = f[4];
  pd.shortest_path = bit(f[5], 6);
  pd.relative = bit(f[5], 5);
  pd.set_origin = bit(f[5], 4);
  pd.reset_error = bit(f[5], 3);
  pd.stop = bit(f[5], 2);
  pd.move = bit(f[5], 1);
  pd.motor_on = bit(f[5], 0);
  return pd;
}

// Byte 0 carries bits 55..48, byte 6 bits 7..0 (manual 2.3).
PdInFrame encode(const ProcessDataIn& pd) {
  PdInFrame f{};
  put_be32(&f[0], pd.position_raw);
  f[4] = pd.error_code;
  f[5] = pd.warning_code;
  f[6] = static_cast<uint8_t>(flag(pd.error, 5) | flag(pd.warning, 4) | flag(pd.done, 3) | flag(pd.busy, 2) |
                              flag(pd.ready, 1) | flag(pd.motor_off, 0));
  return f;
}

ProcessDataIn decode_in(const PdInFrame& f) {
  ProcessDataIn pd;
  pd.position_raw = get_be32(&f[0]);
  pd.error_code = f[4];
  pd.warning_code = f[5];
  pd.error = bit(f[6], 5);
  pd.warning = bit(f[6], 4);
  pd.done = bit(f[6], 3);
  pd.busy = bit(f[6], 2);
  pd.ready = bit(f[6], 1);
  pd.motor_off = bit(f[6], 0);
  return pd;
}

ProcessDataOut decode_out(std::span<const uint8_t> bytes) {
  check_length(bytes.size(), kPdOutBytes, "process data out");
  PdOutFrame f{};
  std::copy(bytes.begin(), bytes.end(), f.begin());
  return decode_out(f);
}

int64_t pd_field_value(std::span<const uint8_t> frame, const PdField& field) {
  uint64_t bits = 0; // at most 7 octets: fits
  for (const uint8_t b : frame) bits = (bits << 8) | b;
  const uint64_t mask = field.bit_length >= 64 ? ~uint64_t{0} : (uint64_t{1} << field.bit_length) - 1;
  const uint64_t v = (bits >> field.bit_offset) & mask;
  if (field.type == PdFieldType::Int32) return static_cast<int32_t>(static_cast<uint32_t>(v));
  return static_cast<int64_t>(v);
}

ProcessDataIn decode_in(std::span<const uint8_t> bytes) {
  check_length(bytes.size(), kPdInBytes, "process data in");
  PdInFrame f{};
  std::copy(bytes.begin(), bytes.end(), f.begin());
  return decode_in(f);
}

} // namespace sreh
