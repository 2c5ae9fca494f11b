// The process-data codec (manual 2.2, 2.3): driven by the field tables in
// process_data.hpp, which state the layout once. A frame is read as one
// big-endian integer (byte 0 most significant, as IO-Link transmits it);
// each row's member goes to / comes from its bits.
#include "device_logic/process_data.hpp"

#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "device_logic/byte_order.hpp"

namespace sreh {
namespace {

constexpr uint64_t field_mask(unsigned bit_length) {
  return bit_length >= 64 ? ~uint64_t{0} : (uint64_t{1} << bit_length) - 1;
}

// A malformed table does not compile: every row inside its frame, no two
// rows on the same bit.
template <const auto& Rows, std::size_t Bytes>
constexpr bool rows_fit_apart() {
  uint64_t used = 0;
  for (const auto& row : Rows) {
    if (row.bit_offset + row.bit_length > Bytes * 8) return false;
    const uint64_t bits = field_mask(row.bit_length) << row.bit_offset;
    if ((used & bits) != 0) return false;
    used |= bits;
  }
  return true;
}
static_assert(rows_fit_apart<kPdOutFields, kPdOutBytes>(), "kPdOutFields: a row outside the frame or on another's bits");
static_assert(rows_fit_apart<kPdInFields, kPdInBytes>(), "kPdInFields: a row outside the frame or on another's bits");

// The wire bits of a member's value: int32 as two's complement, bool 0 / 1.
template <class T>
using WireBits = std::make_unsigned_t<std::conditional_t<std::is_same_v<T, bool>, uint8_t, T>>;

// The rows are unrolled at compile time (one fold over the table), each
// row's member pointer a constant: the compiler emits what a hand-written
// codec would, and the cycle pays nothing for the table (bench/twin_bench.cpp
// BM_PdCodecCycle: as fast as the hand-written codec it replaced).
template <const auto& Rows, std::size_t I, class Pd>
constexpr uint64_t row_bits(const Pd& pd) {
  constexpr const auto& row = Rows[I];
  constexpr auto member = std::get<row.member.index()>(row.member);
  using T = std::remove_cvref_t<decltype(pd.*member)>;
  const uint64_t raw = static_cast<WireBits<T>>(pd.*member);
  return (raw & field_mask(row.bit_length)) << row.bit_offset;
}

template <const auto& Rows, std::size_t I, class Pd>
constexpr void set_row(Pd& pd, uint64_t bits) {
  constexpr const auto& row = Rows[I];
  constexpr auto member = std::get<row.member.index()>(row.member);
  using T = std::remove_cvref_t<decltype(pd.*member)>;
  const uint64_t v = (bits >> row.bit_offset) & field_mask(row.bit_length);
  if constexpr (std::is_same_v<T, bool>) {
    pd.*member = v != 0;
  } else {
    pd.*member = static_cast<T>(static_cast<WireBits<T>>(v)); // int32: two's complement
  }
}

template <const auto& Rows, class Pd, std::size_t Bytes>
std::array<uint8_t, Bytes> encode_rows(const Pd& pd) {
  const uint64_t bits = [&]<std::size_t... I>(std::index_sequence<I...>) {
    return (row_bits<Rows, I>(pd) | ...);
  }(std::make_index_sequence<Rows.size()>{});
  // Byte 0 most significant. Each octet's shift a constant: GCC 12 then
  // emits a byte swap, where be::write's runtime loop costs a third more.
  std::array<uint8_t, Bytes> f{};
  [&]<std::size_t... B>(std::index_sequence<B...>) {
    ((f[B] = static_cast<uint8_t>(bits >> (8 * (Bytes - 1 - B)))), ...);
  }(std::make_index_sequence<Bytes>{});
  return f;
}

// `bits`: the frame as one integer; bits no row names (out: bit 7) are ignored.
template <const auto& Rows, class Pd>
Pd decode_rows(uint64_t bits) {
  Pd pd;
  [&]<std::size_t... I>(std::index_sequence<I...>) { (set_row<Rows, I>(pd, bits), ...); }
  (std::make_index_sequence<Rows.size()>{});
  return pd;
}

void check_length(std::size_t got, std::size_t want, const char* what) {
  if (got != want) {
    throw std::invalid_argument(std::string(what) + " frame must be " + std::to_string(want) +
                                " bytes, got " + std::to_string(got));
  }
}

} // namespace

PdOutFrame encode(const ProcessDataOut& pd) { return encode_rows<kPdOutFields, ProcessDataOut, kPdOutBytes>(pd); }
PdInFrame encode(const ProcessDataIn& pd) { return encode_rows<kPdInFields, ProcessDataIn, kPdInBytes>(pd); }
ProcessDataOut decode_out(const PdOutFrame& f) { return decode_rows<kPdOutFields, ProcessDataOut>(be::read(f)); }
ProcessDataIn decode_in(const PdInFrame& f) { return decode_rows<kPdInFields, ProcessDataIn>(be::read(f)); }

ProcessDataOut decode_out(std::span<const uint8_t> bytes) {
  check_length(bytes.size(), kPdOutBytes, "process data out");
  return decode_rows<kPdOutFields, ProcessDataOut>(be::read(bytes));
}
ProcessDataIn decode_in(std::span<const uint8_t> bytes) {
  check_length(bytes.size(), kPdInBytes, "process data in");
  return decode_rows<kPdInFields, ProcessDataIn>(be::read(bytes));
}

int64_t pd_field_value(std::span<const uint8_t> frame, const PdField& field) {
  const uint64_t v = (be::read(frame) >> field.bit_offset) & field_mask(field.bit_length); // at most 7 octets
  if (field.type == PdFieldType::Int32) return static_cast<int32_t>(static_cast<uint32_t>(v));
  return static_cast<int64_t>(v);
}

} // namespace sreh
