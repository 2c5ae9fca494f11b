// Helpers of the ParameterStore tests (parameter_store_test.cpp,
// parameter_store_image_test.cpp): wire values by the table's types.
#pragma once
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "device_logic/parameter_store.hpp"
#include "device_logic/parameter_table.hpp"

namespace sreh::store_test {

using Bytes = std::vector<uint8_t>;

inline Bytes u8(int64_t v) { return encode_number(ParamType::UInt8, v); }
inline Bytes u16(int64_t v) { return encode_number(ParamType::UInt16, v); }
inline Bytes i32(int64_t v) { return encode_number(ParamType::Int32, v); }
inline Bytes str(const std::string& s) { return Bytes(s.begin(), s.end()); }
inline Bytes cat(std::initializer_list<Bytes> parts) {
  Bytes out;
  for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

// Value of a numeric row as written on the wire.
inline Bytes wire(uint16_t index, uint8_t sub, int64_t v) {
  return encode_number(find_parameter(index, sub)->type, v);
}
inline uint16_t put(ParameterStore& s, uint16_t index, uint8_t sub, int64_t v) {
  return s.write(index, sub, wire(index, sub, v)).error;
}
inline uint16_t cmd(ParameterStore& s, uint8_t c) { return s.write(kIndexSystemCommand, 0, u8(c)).error; }
inline uint16_t ds(ParameterStore& s, DsCommand c) {
  return s.write(kIndexDataStorage, 1, u8(static_cast<uint8_t>(c))).error;
}
inline int64_t read_num(const ParameterStore& s, uint16_t index, uint8_t sub) {
  const IsduResult r = s.read(index, sub);
  EXPECT_TRUE(r.ok()) << index << "." << int(sub) << " error 0x" << std::hex << r.error;
  return decode_number(find_parameter(index, sub)->type, r.data);
}

} // namespace sreh::store_test
