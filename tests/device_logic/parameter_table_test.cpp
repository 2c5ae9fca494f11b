// The parameter table against manual chapter 6 (and 1, 2.2, 2.3, 8), row by row.
#include "device_logic/parameter_table.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <set>
#include <string>

#include "device_logic/data_storage.hpp"
#include "device_logic/units.hpp"

namespace sreh {
namespace {

// One expected row, transcribed from the manual independently of the table.
struct Expected {
  uint16_t index;
  uint8_t sub;
  ParamType type;
  Access access;
  Storage storage;
  int64_t min;
  int64_t max;
  int64_t def;
};

using Ids = std::initializer_list<uint16_t>;
constexpr int64_t kI32Min = std::numeric_limits<int32_t>::min();
constexpr int64_t kI32Max = std::numeric_limits<int32_t>::max();
constexpr int64_t kU32Max = 0xFFFFFFFF;

std::vector<Expected> manual_numeric_rows() {
  using PT = ParamType;
  std::vector<Expected> rows;
  // manual 6.2 / 3.5: motion parameter sets 0..7 = indices 64..71.
  for (int n = 0; n < 8; ++n) {
    const auto i = static_cast<uint16_t>(64 + n);
    rows.push_back({i, 1, PT::UInt16, Access::RW, Storage::Config, 1, 43000, n == 0 ? 300 : 30000}); // 0.1..4300 deg/s
    rows.push_back({i, 2, PT::UInt16, Access::RW, Storage::Config, 1, 1000, 1000});  // 0.1..100 %
    rows.push_back({i, 3, PT::UInt16, Access::RW, Storage::Config, 1, 1000, 1000});  // 0.1..100 %
    rows.push_back({i, 4, PT::UInt16, Access::RW, Storage::Config, 0, 15000, 0});    // 0..15000 g cm^2
    rows.push_back({i, 5, PT::UInt16, Access::RW, Storage::Config, 0, 65535, 146});  // full uint16, 0.1 deg
    rows.push_back({i, 6, PT::UInt16, Access::RW, Storage::Config, 0, 50000, 250});  // 0..5 s, 25 ms
    rows.push_back({i, 7, PT::UInt16, Access::RW, Storage::Config, 0, 50000, 1000}); // 0..5 s, 100 ms
    rows.push_back({i, 8, PT::UInt8, Access::RW, Storage::Config, 0, 1, 1});         // active (default)
  }
  // manual 6.2: 81 position limit, 82 direction, 83 LED, 85 voltage, 86 zero, 87 tracking error.
  rows.push_back({81, 1, PT::Int32, Access::RW, Storage::Config, kI32Min, kI32Max, 0});
  rows.push_back({81, 2, PT::Int32, Access::RW, Storage::Config, kI32Min, kI32Max, 65536}); // 360 deg
  rows.push_back({81, 3, PT::UInt8, Access::RW, Storage::Config, 0, 1, 0});
  rows.push_back({82, 0, PT::UInt8, Access::RW, Storage::Config, 0, 1, 0});
  rows.push_back({83, 0, PT::UInt8, Access::RW, Storage::Config, 0, 2, 1});
  rows.push_back({85, 1, PT::UInt16, Access::RW, Storage::Config, 16000, 23000, 18000});
  rows.push_back({85, 2, PT::UInt16, Access::RW, Storage::Config, 25000, 32000, 30000});
  rows.push_back({86, 0, PT::Int32, Access::RW, Storage::Config, -131072, 131072, 0}); // +-720 deg
  rows.push_back({87, 1, PT::UInt16, Access::RW, Storage::Config, 1, 900, 10}); // 0.1..90 deg, 1 deg (A-PARAM-1)
  rows.push_back({87, 2, PT::UInt8, Access::RW, Storage::Config, 0, 1, 1});
  // manual 6.3: persistent diagnostics, read only.
  rows.push_back({96, 0, PT::UInt32, Access::R, Storage::PersistentDiag, 0, kU32Max, 0});
  for (uint8_t s = 1; s <= 3; ++s) rows.push_back({97, s, PT::UInt32, Access::R, Storage::PersistentDiag, 0, kU32Max, 0});
  for (uint16_t i : Ids{98, 99}) {
    rows.push_back({i, 1, PT::UInt32, Access::R, Storage::PersistentDiag, 0, kU32Max, 0});
    rows.push_back({i, 2, PT::UInt8, Access::R, Storage::PersistentDiag, 0, 255, 0});
  }
  rows.push_back({100, 0, PT::UInt32, Access::R, Storage::PersistentDiag, 0, kU32Max, 0});
  // manual 6.4: volatile diagnostics, read only.
  rows.push_back({32, 0, PT::UInt16, Access::R, Storage::Volatile, 0, 65535, 0});
  rows.push_back({36, 0, PT::UInt8, Access::R, Storage::Volatile, 0, 4, 0});
  rows.push_back({112, 0, PT::UInt8, Access::R, Storage::Volatile, 0, 255, 0});
  rows.push_back({113, 0, PT::UInt16, Access::R, Storage::Volatile, 0, 65535, 0});
  for (uint8_t s = 1; s <= 8; ++s) rows.push_back({114, s, PT::UInt8, Access::R, Storage::Volatile, 0, 255, 0});
  for (uint8_t s = 1; s <= 3; ++s) rows.push_back({115, s, PT::UInt8, Access::R, Storage::Volatile, 0, 255, 0});
  rows.push_back({17343, 0, PT::UInt8, Access::R, Storage::Volatile, 0, 255, 0});
  // manual 6.6: system command, write-only.
  rows.push_back({2, 0, PT::UInt8, Access::W, Storage::Command, 0, 255, 0});
  return rows;
}

TEST(ParameterTable, SortedUniqueAndEveryRowCitesASection) {
  const auto table = parameter_table();
  ASSERT_FALSE(table.empty());
  for (std::size_t i = 0; i < table.size(); ++i) {
    EXPECT_FALSE(table[i].section.empty()) << table[i].index << "." << int(table[i].subindex);
    EXPECT_FALSE(table[i].name.empty());
    if (i > 0) {
      const auto& a = table[i - 1];
      const auto& b = table[i];
      EXPECT_TRUE(a.index < b.index || (a.index == b.index && a.subindex < b.subindex));
    }
  }
}

TEST(ParameterTable, NumericRowsMatchTheManual_6) {
  for (const auto& e : manual_numeric_rows()) {
    SCOPED_TRACE(std::to_string(e.index) + "." + std::to_string(e.sub));
    const ParameterEntry* row = find_parameter(e.index, e.sub);
    ASSERT_NE(row, nullptr);
    EXPECT_EQ(row->type, e.type);
    EXPECT_EQ(row->access, e.access);
    EXPECT_EQ(row->storage, e.storage);
    EXPECT_EQ(row->min, e.min);
    EXPECT_EQ(row->max, e.max);
    EXPECT_EQ(row->default_value, e.def);
  }
}

TEST(ParameterTable, DefaultsInsideTheirRangeAndTypeRange) {
  for (const auto& row : parameter_table()) {
    SCOPED_TRACE(std::to_string(row.index) + "." + std::to_string(row.subindex));
    if (is_numeric(row.type)) {
      EXPECT_LE(row.min, row.max);
      // Write-only command rows carry no default (manual 6.6, iolink.md index 3.1).
      if (row.access != Access::W) {
        EXPECT_GE(row.default_value, row.min);
        EXPECT_LE(row.default_value, row.max);
      }
      const std::size_t bits = 8 * wire_size(row.type);
      if (row.type == ParamType::Int32) {
        EXPECT_GE(row.min, kI32Min);
        EXPECT_LE(row.max, kI32Max);
      } else {
        EXPECT_GE(row.min, 0);
        EXPECT_LE(row.max, (int64_t{1} << bits) - 1);
      }
    } else {
      EXPECT_LE(row.default_text.size(), row.max_length);
      EXPECT_GT(row.max_length, 0u);
    }
  }
}

// manual 3.5.7 / 6.2: position tolerance default 0.1 deg in 2^-19 rev units.
TEST(ParameterTable, ToleranceDefaultIsPointOneDegree) {
  const ParameterEntry* row = find_parameter(64, 5);
  ASSERT_NE(row, nullptr);
  EXPECT_EQ(row->default_value, deg_to_internal_counts(0.1));
  EXPECT_NEAR(static_cast<double>(row->default_value) * row->display_scale, 0.1, 0.0005);
}

// manual 6.2: display units and scales of the raw units.
TEST(ParameterTable, DisplayScalesGiveManualDisplayUnits) {
  auto display_default = [](uint16_t i, uint8_t s) {
    const ParameterEntry* row = find_parameter(i, s);
    return static_cast<double>(row->default_value) * row->display_scale;
  };
  EXPECT_DOUBLE_EQ(display_default(64, 1), 30.0);   // deg/s
  EXPECT_DOUBLE_EQ(display_default(65, 1), 3000.0); // deg/s
  EXPECT_DOUBLE_EQ(display_default(64, 2), 100.0);  // %
  EXPECT_DOUBLE_EQ(display_default(64, 6), 25.0);   // ms
  EXPECT_DOUBLE_EQ(display_default(64, 7), 100.0);  // ms
  EXPECT_DOUBLE_EQ(display_default(81, 2), 360.0);  // deg
  EXPECT_DOUBLE_EQ(display_default(85, 1), 18.0);   // V
  EXPECT_DOUBLE_EQ(display_default(85, 2), 30.0);   // V
  EXPECT_DOUBLE_EQ(display_default(87, 1), 1.0);    // deg (A-PARAM-1)
  EXPECT_DOUBLE_EQ(static_cast<double>(find_parameter(86, 0)->max) * find_parameter(86, 0)->display_scale, 720.0);
  EXPECT_DOUBLE_EQ(static_cast<double>(find_parameter(87, 1)->max) * find_parameter(87, 1)->display_scale, 90.0);
  EXPECT_DOUBLE_EQ(find_parameter(98, 2)->display_scale, 0.5); // 0.5 degC (6.3)
}

// manual 6.5 identification texts, 1 profile list.
TEST(ParameterTable, IdentificationRowsMatchTheManual_6_5) {
  auto text = [](uint16_t i) { return std::string(find_parameter(i, 0)->default_text); };
  EXPECT_EQ(text(16), "Afag");
  EXPECT_EQ(text(17), "www.afag.com");
  EXPECT_EQ(text(18), "Smart Rotary Module SREH-50-IOL");
  EXPECT_EQ(text(19), "SREH-50-IOL");
  EXPECT_EQ(text(20), "Smart electrical rotatary module with hollow shaft SREH-50-IOL"); // manual 6.5 DE (sic)
  for (uint16_t i : Ids{21, 22, 23, 17342}) {
    EXPECT_FALSE(text(i).empty()) << i;
    EXPECT_EQ(find_parameter(i, 0)->access, Access::R);
  }
  for (uint16_t i : Ids{24, 25, 26}) {
    EXPECT_EQ(text(i), "***");
    EXPECT_EQ(find_parameter(i, 0)->access, Access::RW);
    EXPECT_EQ(find_parameter(i, 0)->max_length, 32u);
  }
  const std::string profiles = text(13);
  ASSERT_EQ(profiles.size(), 6u);
  auto u16 = [&](std::size_t k) { return (uint8_t(profiles[2 * k]) << 8) | uint8_t(profiles[2 * k + 1]); };
  EXPECT_EQ(u16(0), 0x4000); // Common Profile
  EXPECT_EQ(u16(1), 0x8101); // Locator
  EXPECT_EQ(u16(2), 0x0031); // Firmware Update
  EXPECT_EQ(row_type_text(*find_parameter(13, 0)), "uint16[]");
}

// manual 2.2 / 2.3: the PD descriptors name every field.
TEST(ParameterTable, ProcessDataDescriptorsNameEveryField) {
  const std::string in(find_parameter(14, 0)->default_text);
  for (const char* f : {"ActualPosition", "ErrorCode", "WarningCode", "Error:", "Warning:", "Done", "Busy",
                        "Ready", "MotorOff"})
    EXPECT_NE(in.find(f), std::string::npos) << f;
  const std::string out(find_parameter(15, 0)->default_text);
  for (const char* f : {"TargetPosition", "MotionParameterSet", "ShortestPath", "Relative", "SetOrigin",
                        "ResetError", "Stop", "Move", "MotorOn"})
    EXPECT_NE(out.find(f), std::string::npos) << f;
}

// manual 6.4: 37 OctetString3[4], 40 / 41 process data images of 7 / 6 octets.
TEST(ParameterTable, VolatileOctetRows) {
  EXPECT_EQ(find_parameter(37, 0)->max_length, 12u);
  EXPECT_EQ(find_parameter(40, 0)->max_length, 7u);
  EXPECT_EQ(find_parameter(41, 0)->max_length, 6u);
  for (uint16_t i : Ids{37, 40, 41}) EXPECT_EQ(find_parameter(i, 0)->access, Access::R);
}

// Exactly the indices chapter 6 lists (+ index 3 Data Storage of chapter 8).
TEST(ParameterTable, IndexSetIsTheManuals) {
  std::set<uint16_t> expected = {2,  3,  13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 32, 36, 37, 40,
                                 41, 81, 82, 83, 85, 86, 87, 96, 97, 98, 99, 100, 112, 113, 114, 115, 17342, 17343};
  for (uint16_t i = 64; i <= 71; ++i) expected.insert(i);
  std::set<uint16_t> actual;
  for (const auto& row : parameter_table()) actual.insert(row.index);
  EXPECT_EQ(actual, expected);
  for (uint16_t i : expected) EXPECT_TRUE(index_exists(i)) << i;
  for (uint16_t i : Ids{0, 1, 4, 12, 27, 72, 80, 84, 88, 101, 116, 999, 17341, 17344, 65535})
    EXPECT_FALSE(index_exists(i)) << i;
}

TEST(ParameterTable, RecordsAndLookups) {
  EXPECT_EQ(find_parameter(64, 0), nullptr); // a record: use record_members
  EXPECT_EQ(find_parameter(64, 9), nullptr);
  EXPECT_EQ(find_parameter(82, 1), nullptr);
  for (uint16_t i : Ids{3, 64, 71, 81, 85, 87, 97, 98, 99, 114, 115}) EXPECT_TRUE(is_record(i)) << i;
  for (uint16_t i : Ids{2, 24, 40, 82, 86, 96, 17342}) EXPECT_FALSE(is_record(i)) << i;
  const auto members = record_members(64);
  ASSERT_EQ(members.size(), 8u);
  for (std::size_t k = 0; k < members.size(); ++k) EXPECT_EQ(members[k]->subindex, k + 1);
  EXPECT_EQ(record_members(114).size(), 8u);
  EXPECT_EQ(record_members(115).size(), 3u);
  EXPECT_TRUE(record_members(82).empty());
  EXPECT_EQ(find_parameter(17343, 0)->index, 17343);
  EXPECT_EQ(row_position(17342, 1), -1);
}

// IO-Link transmits big-endian (manual 2.5).
TEST(ParameterTable, NumberCodecIsBigEndianAndSigned) {
  EXPECT_EQ(encode_number(ParamType::UInt16, 30000), (std::vector<uint8_t>{0x75, 0x30}));
  EXPECT_EQ(encode_number(ParamType::Int32, -65536), (std::vector<uint8_t>{0xFF, 0xFF, 0x00, 0x00}));
  EXPECT_EQ(encode_number(ParamType::UInt8, 2), (std::vector<uint8_t>{0x02}));
  const std::vector<uint8_t> neg{0xFF, 0xFE, 0x00, 0x00};
  EXPECT_EQ(decode_number(ParamType::Int32, neg), -131072);
  EXPECT_EQ(decode_number(ParamType::UInt32, neg), 0xFFFE0000);
  EXPECT_EQ(wire_size(ParamType::String), 0u);
}

// manual 8 / iolink.md: the Data Storage set is the configuration plus the tags.
TEST(DataStorage, SetHoldsConfigurationAndTagsOnly) {
  std::set<uint16_t> expected = {24, 25, 26, 81, 82, 83, 85, 86, 87};
  for (uint16_t i = 64; i <= 71; ++i) expected.insert(i);
  std::set<uint16_t> actual;
  for (const auto& e : data_storage_entries()) {
    EXPECT_EQ(e.subindex, 0);
    actual.insert(e.index);
  }
  EXPECT_EQ(actual, expected);
  EXPECT_EQ(actual.size(), data_storage_entries().size());
}

TEST(DataStorage, IndexListCodec) {
  const std::vector<DsEntry> entries{{64, 0}, {0x1234, 7}};
  const auto bytes = encode_index_list(entries);
  EXPECT_EQ(bytes, (std::vector<uint8_t>{0, 64, 0, 0x12, 0x34, 7, 0, 0}));
  EXPECT_EQ(decode_index_list(bytes), entries);
  EXPECT_FALSE(decode_index_list(std::vector<uint8_t>{0, 64, 0}).has_value());       // no terminator
  EXPECT_FALSE(decode_index_list(std::vector<uint8_t>{0, 64, 0, 0, 0, 9}).has_value()); // bytes after it
  EXPECT_FALSE(decode_index_list(std::vector<uint8_t>{0, 64}).has_value());
}

TEST(DataStorage, Crc32CheckValue) {
  const std::string s = "123456789";
  const std::vector<uint8_t> bytes(s.begin(), s.end());
  EXPECT_EQ(crc32(bytes), 0xCBF43926u); // IEEE 802.3 check value
  EXPECT_EQ(crc32(std::span(bytes).subspan(4), crc32(std::span(bytes).first(4))), 0xCBF43926u);
}

TEST(DataStorage, StatePropertyBits) {
  EXPECT_EQ(ds_state_property(DsState::Inactive, false), 0x00);
  EXPECT_EQ(ds_state_property(DsState::Upload, false), 0x02);
  EXPECT_EQ(ds_state_property(DsState::Download, true), 0x84);
}

} // namespace
} // namespace sreh
