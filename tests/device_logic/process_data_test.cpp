// Manual 2.2 (6 bytes out), 2.3 (7 bytes in), 2.5 (position coding): every
// field's bit position, round trips, wrong lengths.
#include <gtest/gtest.h>

#include <stdexcept>
#include <type_traits>
#include <variant>
#include <vector>

#include "device_logic/process_data.hpp"

namespace sreh {
namespace {

TEST(ProcessDataOut, FieldBitPositions_2_2) {
  struct Case { ProcessDataOut pd; PdOutFrame frame; };
  auto with = [](auto f) { ProcessDataOut p; f(p); return p; };
  const std::vector<Case> cases = {
      {with([](auto& p) { p.motor_on = true; }), {0, 0, 0, 0, 0, 0x01}},
      {with([](auto& p) { p.move = true; }), {0, 0, 0, 0, 0, 0x02}},
      {with([](auto& p) { p.stop = true; }), {0, 0, 0, 0, 0, 0x04}},
      {with([](auto& p) { p.reset_error = true; }), {0, 0, 0, 0, 0, 0x08}},
      {with([](auto& p) { p.set_origin = true; }), {0, 0, 0, 0, 0, 0x10}},
      {with([](auto& p) { p.relative = true; }), {0, 0, 0, 0, 0, 0x20}},
      {with([](auto& p) { p.shortest_path = true; }), {0, 0, 0, 0, 0, 0x40}},
      {with([](auto& p) { p.parameter_set = 7; }), {0, 0, 0, 0, 7, 0}},
      {with([](auto& p) { p.target_raw = 0x12345678; }), {0x12, 0x34, 0x56, 0x78, 0, 0}}, // bits 47..16, big-endian
      {with([](auto& p) { p.target_raw = -1; }), {0xFF, 0xFF, 0xFF, 0xFF, 0, 0}},
  };
  for (const auto& c : cases) {
    EXPECT_EQ(encode(c.pd), c.frame);
    EXPECT_EQ(decode_out(c.frame), c.pd);
  }
  // Bit 7 of the last byte is not used: ignored on decode.
  EXPECT_EQ(decode_out(PdOutFrame{0, 0, 0, 0, 0, 0x80}), ProcessDataOut{});
}

TEST(ProcessDataIn, FieldBitPositions_2_3) {
  struct Case { ProcessDataIn pd; PdInFrame frame; };
  auto with = [](auto f) { ProcessDataIn p; f(p); return p; };
  const std::vector<Case> cases = {
      {with([](auto& p) { p.motor_off = true; }), {0, 0, 0, 0, 0, 0, 0x01}},
      {with([](auto& p) { p.ready = true; }), {0, 0, 0, 0, 0, 0, 0x02}},
      {with([](auto& p) { p.busy = true; }), {0, 0, 0, 0, 0, 0, 0x04}},
      {with([](auto& p) { p.done = true; }), {0, 0, 0, 0, 0, 0, 0x08}},
      {with([](auto& p) { p.warning = true; }), {0, 0, 0, 0, 0, 0, 0x10}},
      {with([](auto& p) { p.error = true; }), {0, 0, 0, 0, 0, 0, 0x20}},
      {with([](auto& p) { p.warning_code = 0xA0; }), {0, 0, 0, 0, 0, 0xA0, 0}}, // bits 15..8
      {with([](auto& p) { p.error_code = 0x81; }), {0, 0, 0, 0, 0x81, 0, 0}},   // bits 23..16
      {with([](auto& p) { p.position_raw = -65536; }), {0xFF, 0xFF, 0x00, 0x00, 0, 0, 0}}, // -360 deg
  };
  for (const auto& c : cases) {
    EXPECT_EQ(encode(c.pd), c.frame);
    EXPECT_EQ(decode_in(c.frame), c.pd);
  }
}

TEST(ProcessData, RoundTripAllFields_2_2_2_3) {
  ProcessDataOut out{-123456789, 5, true, false, true, false, true, false, true};
  EXPECT_EQ(decode_out(encode(out)), out);
  ProcessDataIn in{2147483647, 0x55, 0xE0, true, true, false, true, false, false};
  EXPECT_EQ(decode_in(encode(in)), in);
}

TEST(ProcessData, WrongLengthIsRefusedWithClearError_2_2) {
  const std::vector<uint8_t> five(5, 0), eight(8, 0);
  try {
    decode_out(std::span<const uint8_t>(five));
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "process data out frame must be 6 bytes, got 5");
  }
  EXPECT_THROW(decode_in(std::span<const uint8_t>(eight)), std::invalid_argument);
  EXPECT_NO_THROW(decode_in(std::span<const uint8_t>(std::vector<uint8_t>(7, 0))));
}

TEST(PositionCoding, ExamplesOfTheTable_2_5) {
  EXPECT_EQ(wrap_wire_position(0), 0);
  EXPECT_EQ(wrap_wire_position(65536), 65536);                  // 360 deg
  EXPECT_EQ(wrap_wire_position(-65536), -65536);                // -360 deg
  EXPECT_EQ(wrap_wire_position(-1), -1);                        // approx -0.0055 deg
  EXPECT_EQ(wrap_wire_position(int64_t{1} << 31), INT32_MIN);   // +2^15 rev overflows to -2^15 rev
  EXPECT_EQ(wrap_wire_position((int64_t{1} << 31) + 65536), INT32_MIN + 65536);
  EXPECT_EQ(wrap_wire_position(-(int64_t{1} << 31) - 1), INT32_MAX);
}

} // namespace
// The layout table (kPdOutFields / kPdInFields, used by the IODD-like
// export) must say what the codec does: each field set alone to all ones
// lands exactly on its declared bits (manual 2.2, 2.3).
template <std::size_t Bytes>
uint64_t frame_bits(const std::array<uint8_t, Bytes>& f) {
  uint64_t v = 0;
  for (uint8_t b : f) v = (v << 8) | b; // byte 0 is the most significant (big-endian)
  return v;
}
uint64_t field_mask(const PdField& f) { return ((uint64_t{1} << f.bit_length) - 1) << f.bit_offset; }

// A struct with the field of this name all ones, the others 0: the mapping
// written out by hand, independent of the table.
ProcessDataOut out_with_all_ones(std::string_view name) {
  ProcessDataOut p;
  if (name == "target_raw") p.target_raw = -1;
  if (name == "parameter_set") p.parameter_set = 0xFF;
  p.shortest_path = name == "shortest_path";
  p.relative = name == "relative";
  p.set_origin = name == "set_origin";
  p.reset_error = name == "reset_error";
  p.stop = name == "stop";
  p.move = name == "move";
  p.motor_on = name == "motor_on";
  return p;
}
ProcessDataIn in_with_all_ones(std::string_view name) {
  ProcessDataIn p;
  if (name == "position_raw") p.position_raw = -1;
  if (name == "error_code") p.error_code = 0xFF;
  if (name == "warning_code") p.warning_code = 0xFF;
  p.error = name == "error";
  p.warning = name == "warning";
  p.done = name == "done";
  p.busy = name == "busy";
  p.ready = name == "ready";
  p.motor_off = name == "motor_off";
  return p;
}

TEST(ProcessDataLayout, OutFieldsMatchTheCodec_2_2) {
  uint64_t covered = 0;
  for (const PdField& f : kPdOutFields) {
    EXPECT_EQ(frame_bits(encode(out_with_all_ones(f.name))), field_mask(f)) << f.name;
    covered |= field_mask(f);
  }
  EXPECT_EQ(covered, 0xFFFFFFFFFFFFull & ~0x80ull); // every bit but the reserved bit 7 (manual 2.2)
}

TEST(ProcessDataLayout, InFieldsMatchTheCodec_2_3) {
  for (const PdField& f : kPdInFields) EXPECT_EQ(frame_bits(encode(in_with_all_ones(f.name))), field_mask(f)) << f.name;
}

// A struct with the member of `row` set to all ones through the row's own
// member pointer, the others 0.
template <class Pd>
Pd all_ones_through(const PdFieldOf<Pd>& row) {
  Pd p;
  std::visit([&p](auto member) {
    using T = std::remove_cvref_t<decltype(p.*member)>;
    if constexpr (std::is_same_v<T, bool>) p.*member = true;
    else p.*member = static_cast<T>(~T{0});
  }, row.member);
  return p;
}

// The codec reads the rows (issue 30): each row's member pointer is the
// member its name says, it lands exactly on the row's bits and those bits
// decode back into it alone; no two rows share a member or a bit.
template <class Pd, std::size_t N, std::size_t Bytes>
void expect_rows_agree(const std::array<PdFieldOf<Pd>, N>& rows, Pd (*by_name)(std::string_view),
                       Pd (*decode)(const std::array<uint8_t, Bytes>&)) {
  uint64_t covered = 0;
  for (std::size_t i = 0; i < N; ++i) {
    const PdFieldOf<Pd>& row = rows[i];
    const Pd through_row = all_ones_through(row);
    EXPECT_EQ(through_row, by_name(row.name)) << row.name << ": the row's member is another field";
    EXPECT_EQ(static_cast<std::size_t>(row.type), row.member.index()) << row.name;
    const std::array<uint8_t, Bytes> frame = encode(through_row);
    EXPECT_EQ(frame_bits(frame), field_mask(row)) << row.name;
    EXPECT_EQ(decode(frame), through_row) << row.name;
    EXPECT_EQ(covered & field_mask(row), 0u) << row.name << " overlaps another row";
    covered |= field_mask(row);
    for (std::size_t j = 0; j < i; ++j) EXPECT_NE(rows[j].member, row.member) << row.name << ", " << rows[j].name;
  }
}

TEST(ProcessDataLayout, EachRowsMemberAndBitsAgree_2_2_2_3) {
  expect_rows_agree<ProcessDataOut, kPdOutFields.size(), kPdOutBytes>(kPdOutFields, out_with_all_ones, decode_out);
  expect_rows_agree<ProcessDataIn, kPdInFields.size(), kPdInBytes>(kPdInFields, in_with_all_ones, decode_in);
}

// The decoded views read each field through its row: the value the codec
// wrote comes back, the position sign-extended (manual 2.2, 2.3, 2.5).
TEST(ProcessDataLayout, TableFieldValuesAreTheCodecs_2_2_2_3) {
  ProcessDataOut out;
  out.target_raw = -123456;
  out.parameter_set = 5;
  out.relative = true;
  out.motor_on = true;
  const PdOutFrame of = encode(out);
  for (const PdField& f : kPdOutFields) {
    int64_t want = 0;
    if (f.name == "target_raw") want = -123456;
    if (f.name == "parameter_set") want = 5;
    if (f.name == "relative" || f.name == "motor_on") want = 1;
    EXPECT_EQ(pd_field_value(of, f), want) << f.name;
  }
  ProcessDataIn in;
  in.position_raw = 2147483647;
  in.error_code = 0x90;
  in.done = true;
  const PdInFrame inf = encode(in);
  for (const PdField& f : kPdInFields) {
    int64_t want = 0;
    if (f.name == "position_raw") want = 2147483647;
    if (f.name == "error_code") want = 0x90;
    if (f.name == "done") want = 1;
    EXPECT_EQ(pd_field_value(inf, f), want) << f.name;
  }
  EXPECT_EQ(kPdOutFields[0].deg_name, "target_deg");
  EXPECT_EQ(kPdInFields[0].deg_name, "position_deg");
}

} // namespace sreh
