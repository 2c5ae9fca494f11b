// The acyclic (ISDU) parameter table, manual chapter 6: declared once, read
// by ISDU validation, `params`, data storage and the docs (docs/style.md 5).
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sreh {

enum class ParamType { UInt8, UInt16, UInt32, Int32, String, OctetString, Record };
enum class Access { R, RW, W };
// Where a value lives: configuration survives a power cycle (non-volatile),
// persistent diagnostics too; volatile values are computed by the device.
enum class Storage { Config, PersistentDiag, Volatile, Identification, Command };

struct ParameterEntry {
  uint16_t index;
  uint8_t subindex;             // 0: a plain variable (or the whole record)
  std::string_view name;        // manual name
  ParamType type;
  Access access;
  Storage storage;
  std::string_view raw_unit;    // what one LSB is, e.g. "0.1 deg/s"
  std::string_view display_unit;
  double display_scale;         // display value = raw * display_scale
  int64_t min;                  // raw range (numeric types)
  int64_t max;
  int64_t default_value;        // raw default (numeric types)
  std::string_view default_text;// default for strings
  std::string_view section;     // manual section, e.g. "6.2"
  std::size_t max_length = 0;   // strings / octet strings: maximum octets
  std::string_view record_name = {}; // the record a member belongs to, e.g. "Position limit"
  std::string_view type_label = {};  // manual's type text where it differs, e.g. "uint16[]"
  std::string_view notes = {};       // value meanings, e.g. "0: clockwise, 1: counterclockwise"
};

// Every row of the table, in index/subindex order.
std::span<const ParameterEntry> parameter_table();

// Row of a variable or record member; nullptr if none. A record index
// (64..71, 81, 85, 87, 97..99, 114, 115) with subindex 0 returns nullptr:
// use record_members().
const ParameterEntry* find_parameter(uint16_t index, uint8_t subindex);
// The members of a record index in subindex order (empty if not a record).
std::vector<const ParameterEntry*> record_members(uint16_t index);
bool index_exists(uint16_t index);

bool is_record(uint16_t index);
// Position of a row in parameter_table(), -1 if none; O(1) for indices < 128.
int row_position(uint16_t index, uint8_t subindex);
std::size_t parameter_row_count();
// Manual type text of a row: type_label if set, else type_name(type).
std::string_view row_type_text(const ParameterEntry& row);
std::string_view storage_name(Storage storage);
bool is_numeric(ParamType type);

// Octets of a numeric type on the wire (1, 2 or 4); 0 for strings.
std::size_t wire_size(ParamType type);
std::string_view type_name(ParamType type);
std::string_view access_name(Access access);

// Big-endian encoding of numeric values, as ISDU transmits them.
std::vector<uint8_t> encode_number(ParamType type, int64_t raw);
int64_t decode_number(ParamType type, std::span<const uint8_t> bytes); // bytes.size() == wire_size(type)

} // namespace sreh
