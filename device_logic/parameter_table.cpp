// The parameter table of manual chapter 6 as one constexpr array (docs/style.md 5).
// Every row cites its manual section; ISDU validation, `params`, Data Storage
// and the memory image all read this table, no range is repeated elsewhere.
// Constants the manual leaves open are docs/assumptions/parameters.md entries.
#include "device_logic/parameter_table.hpp"
#include "device_logic/byte_order.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>

namespace sreh {
namespace {

using PT = ParamType;
using AC = Access;
using ST = Storage;

constexpr int64_t kU8Max = 0xFF;
constexpr int64_t kU16Max = 0xFFFF;
constexpr int64_t kU32Max = 0xFFFFFFFF;
constexpr int64_t kI32Min = std::numeric_limits<int32_t>::min();
constexpr int64_t kI32Max = std::numeric_limits<int32_t>::max();
constexpr double kWireDegPerCount = 360.0 / 65536.0;   // manual 2.5: 2^-16 * 360 deg
constexpr double kInternalDegPerCount = 360.0 / 524288.0; // manual 6.2, 64.5: 2^-19 * 360 deg
constexpr double kHoursPerMinute = 1.0 / 60.0;

// A numeric row.
constexpr ParameterEntry num(uint16_t index, uint8_t sub, std::string_view name, PT type, AC access,
                             ST storage, std::string_view raw_unit, std::string_view display_unit,
                             double scale, int64_t min, int64_t max, int64_t def, std::string_view section,
                             std::string_view record = {}, std::string_view notes = {}) {
  return ParameterEntry{index, sub, name, type, access, storage, raw_unit, display_unit, scale, min, max,
                        def, {}, section, 0, record, {}, notes};
}

// A string / octet-string / opaque-record row.
constexpr ParameterEntry text(uint16_t index, uint8_t sub, std::string_view name, PT type, AC access,
                              ST storage, std::string_view def, std::size_t max_length,
                              std::string_view section, std::string_view type_label = {},
                              std::string_view notes = {}) {
  // max_length 0: a fixed text whose length is its default's.
  return ParameterEntry{index, sub, name, type, access, storage, "", "", 1.0, 0, 0, 0, def, section,
                        max_length == 0 ? def.size() : max_length, {}, type_label, notes};
}

// Motion parameter sets 0..7 = indices 64..71, manual 6.2 and 3.5. Only the
// default speed differs: 30 deg/s for set 0, 3000 deg/s for sets 1..7.
constexpr std::array<std::string_view, 8> kSetNames = {
    "Motion parameter set 0", "Motion parameter set 1", "Motion parameter set 2", "Motion parameter set 3",
    "Motion parameter set 4", "Motion parameter set 5", "Motion parameter set 6", "Motion parameter set 7"};

constexpr std::array<ParameterEntry, 8> motion_set(int n) {
  const auto index = static_cast<uint16_t>(64 + n);
  const std::string_view rec = kSetNames[static_cast<std::size_t>(n)];
  const int64_t speed_default = n == 0 ? 300 : 30000; // 30 deg/s resp. 3000 deg/s
  return {{
      num(index, 1, "Maximum speed", PT::UInt16, AC::RW, ST::Config, "0.1 deg/s", "deg/s", 0.1, 1, 43000,
          speed_default, "6.2, 3.5.3", rec, "0.1 .. 4300 deg/s"),
      num(index, 2, "Acceleration factor", PT::UInt16, AC::RW, ST::Config, "0.1 %", "%", 0.1, 1, 1000, 1000,
          "6.2, 3.5.4", rec, "0.1 .. 100 % of alpha100%"),
      num(index, 3, "Jerk factor", PT::UInt16, AC::RW, ST::Config, "0.1 %", "%", 0.1, 1, 1000, 1000,
          "6.2, 3.5.5", rec, "0.1 .. 100 %; 100 % reaches alpha100% in 10 ms"),
      num(index, 4, "Load (mass moment of inertia)", PT::UInt16, AC::RW, ST::Config, "g cm^2", "g cm^2", 1.0,
          0, 15000, 0, "6.2, 3.5.6", rec),
      // Default 0.1 deg = round(0.1 / 360 * 2^19) = 146 counts.
      num(index, 5, "Position tolerance", PT::UInt16, AC::RW, ST::Config, "2^-19*360 deg", "deg",
          kInternalDegPerCount, 0, kU16Max, 146, "6.2, 3.5.7", rec, "full uint16 range; default 0.1 deg"),
      num(index, 6, "Waiting time", PT::UInt16, AC::RW, ST::Config, "0.1 ms", "ms", 0.1, 0, 50000, 250,
          "6.2, 3.5.7", rec, "0 .. 5 s"),
      num(index, 7, "Settling-timeout", PT::UInt16, AC::RW, ST::Config, "0.1 ms", "ms", 0.1, 0, 50000, 1000,
          "6.2, 3.5.8", rec, "0 .. 5 s"),
      num(index, 8, "Settling-timeout active", PT::UInt8, AC::RW, ST::Config, "-", "", 1.0, 0, 1, 1,
          "6.2, 3.5.8", rec, "0: inactive, 1: active"),
  }};
}

constexpr std::string_view kProfiles{"\x40\x00\x81\x01\x00\x31", 6}; // 0x4000, 0x8101, 0x0031 (manual 1)
// Process data descriptors composed from manual 2.3 (in) and 2.2 (out), A-PARAM-3.
constexpr std::string_view kPdInDescriptor =
    "ActualPosition:int32@55..24;ErrorCode:uint8@23..16;WarningCode:uint8@15..8;"
    "Error:bit@5;Warning:bit@4;Done:bit@3;Busy:bit@2;Ready:bit@1;MotorOff:bit@0";
constexpr std::string_view kPdOutDescriptor =
    "TargetPosition:int32@47..16;MotionParameterSet:uint8@15..8;ShortestPath:bit@6;Relative:bit@5;"
    "SetOrigin:bit@4;ResetError:bit@3;Stop:bit@2;Move:bit@1;MotorOn:bit@0";
constexpr std::string_view kSerialNumber = "TWIN-0000001";     // A-PARAM-4
constexpr std::string_view kHardwareRevision = "1.0";         // A-PARAM-4
constexpr std::string_view kFirmwareRevision = "1.0.0-twin";  // A-PARAM-4
constexpr std::string_view kHardwareId = "SREH-50-IOL-HW1.0"; // A-PARAM-4
constexpr std::size_t kTagMaxOctets = 32;                     // A-PARAM-5
constexpr std::size_t kIsduMaxOctets = 232;                   // IO-Link ISDU data limit

constexpr std::array kHead = {
    // 6.6 system command (index 2, write-only); Device handles 80..83, 126..171.
    num(2, 0, "System command", PT::UInt8, AC::W, ST::Command, "-", "", 1.0, 0, kU8Max, 0, "6.6", {},
        "1..6 block parameterisation, 80..83 firmware update, 126/127 locator, 128 device reset, "
        "129 application reset, 130 restore factory, 131 back-to-box, 160/161 reset temperature "
        "diagnostics, 170/171 apply/store position zero"),
    // 8 device exchange: Data Storage index 3 (iolink.md "Data Storage").
    num(3, 1, "DS_Command", PT::UInt8, AC::W, ST::Command, "-", "", 1.0, 1, 5, 0, "8", "Data Storage",
        "1 UploadStart, 2 UploadEnd, 3 DownloadStart, 4 DownloadEnd, 5 Break"),
    num(3, 2, "State_Property", PT::UInt8, AC::R, ST::Volatile, "-", "", 1.0, 0, kU8Max, 0, "8",
        "Data Storage", "bit 7 upload request; bits 2..1 0 inactive, 1 upload, 2 download"),
    num(3, 3, "Data_Storage_Size", PT::UInt32, AC::R, ST::Volatile, "octet", "octet", 1.0, 0, kU32Max, 0, "8",
        "Data Storage", "per entry 2 index + 1 subindex + 1 length + data octets (A-PARAM-7)"),
    num(3, 4, "Parameter_Checksum", PT::UInt32, AC::R, ST::Volatile, "-", "", 1.0, 0, kU32Max, 0, "8",
        "Data Storage", "CRC-32 over the Data Storage set (A-PARAM-7)"),
    ParameterEntry{3, 5, "Index_List", PT::OctetString, AC::R, ST::Volatile, "", "", 1.0, 0, 0, 0, "", "8",
                   kIsduMaxOctets, "Data Storage", "OctetString",
                   "entries index(2) + subindex(1), ended by index 0 (2 octets)"},
    // 6.5 identification data.
    text(13, 0, "Profile characteristics", PT::OctetString, AC::R, ST::Identification, kProfiles, 6, "6.5, 1",
         "uint16[]", "0x4000 Common Profile, 0x8101 Locator, 0x0031 Firmware Update"),
    text(14, 0, "Process data input descriptor", PT::String, AC::R, ST::Identification, kPdInDescriptor, 0, "6.5, 2.3", "string[]"),
    text(15, 0, "Process data output descriptor", PT::String, AC::R, ST::Identification, kPdOutDescriptor, 0, "6.5, 2.2", "string[]"),
    text(16, 0, "Manufacturer name", PT::String, AC::R, ST::Identification, "Afag", 0, "6.5"),
    text(17, 0, "Manufacturer text", PT::String, AC::R, ST::Identification, "www.afag.com", 0, "6.5"),
    text(18, 0, "Product name", PT::String, AC::R, ST::Identification, "Smart Rotary Module SREH-50-IOL", 0,
         "6.5"),
    text(19, 0, "Product ID", PT::String, AC::R, ST::Identification, "SREH-50-IOL", 0, "6.5"),
    text(20, 0, "Product text", PT::String, AC::R, ST::Identification, // German original (sic), A-PARAM-15
         "Smart electrical rotatary module with hollow shaft SREH-50-IOL", 0, "6.5"),
    text(21, 0, "Serial number", PT::String, AC::R, ST::Identification, kSerialNumber, 0,
         "6.5"),
    text(22, 0, "Hardware revision", PT::String, AC::R, ST::Identification, kHardwareRevision, 0, "6.5"),
    text(23, 0, "Firmware revision", PT::String, AC::R, ST::Identification, kFirmwareRevision, 0, "6.5"),
    text(24, 0, "Application specific tag", PT::String, AC::RW, ST::Identification, "***", kTagMaxOctets,
         "6.5"),
    text(25, 0, "Function tag", PT::String, AC::RW, ST::Identification, "***", kTagMaxOctets, "6.5"),
    text(26, 0, "Location tag", PT::String, AC::RW, ST::Identification, "***", kTagMaxOctets, "6.5"),
    // 6.4 volatile diagnostics (values come from the Device).
    num(32, 0, "Error counter", PT::UInt16, AC::R, ST::Volatile, "1", "1", 1.0, 0, kU16Max, 0, "6.4", {},
        "errors since power-on"),
    num(36, 0, "Device status", PT::UInt8, AC::R, ST::Volatile, "-", "", 1.0, 0, 4, 0, "6.4", {},
        "0 OK, 1 maintenance required, 2 out of specification, 3 functional check, 4 failure"),
    text(37, 0, "Detailed device status", PT::OctetString, AC::R, ST::Volatile, "", 12, "6.4",
         "OctetString3[4]", "[qualifier][code hi][code lo] per pending event"),
    text(40, 0, "Image of the process data inputs", PT::Record, AC::R, ST::Volatile, "", 7, "6.4, 2.3",
         "record (7 octets)"),
    text(41, 0, "Image of the process data outputs", PT::Record, AC::R, ST::Volatile, "", 6, "6.4, 2.2",
         "record (6 octets)"),
};

constexpr std::array kTail = {
    // 6.2 configuration (after the motion sets 64..71).
    num(81, 1, "Minimum", PT::Int32, AC::RW, ST::Config, "2^-16*360 deg", "deg", kWireDegPerCount, kI32Min,
        kI32Max, 0, "6.2", "Position limit"),
    num(81, 2, "Maximum", PT::Int32, AC::RW, ST::Config, "2^-16*360 deg", "deg", kWireDegPerCount, kI32Min,
        kI32Max, 65536, "6.2", "Position limit", "default 360 deg; must be >= 81.1 (A-PARAM-6)"),
    num(81, 3, "Position limitation active", PT::UInt8, AC::RW, ST::Config, "-", "", 1.0, 0, 1, 0, "6.2",
        "Position limit", "0: inactive, 1: active"),
    num(82, 0, "Positive direction of rotation", PT::UInt8, AC::RW, ST::Config, "-", "", 1.0, 0, 1, 0,
        "6.2, 4.2", {}, "0: clockwise, 1: counterclockwise"),
    num(83, 0, "LED band mode", PT::UInt8, AC::RW, ST::Config, "-", "", 1.0, 0, 2, 1, "6.2, 3.1", {},
        "0: off, 1: on, 2: errors and warnings only"),
    num(85, 1, "Minimum", PT::UInt16, AC::RW, ST::Config, "mV", "V", 0.001, 16000, 23000, 18000, "6.2",
        "Valid range of motor voltage"),
    num(85, 2, "Maximum", PT::UInt16, AC::RW, ST::Config, "mV", "V", 0.001, 25000, 32000, 30000, "6.2",
        "Valid range of motor voltage"),
    num(86, 0, "Position zero", PT::Int32, AC::RW, ST::Config, "2^-16*360 deg", "deg", kWireDegPerCount,
        -131072, 131072, 0, "6.2, 4.3", {}, "-720 .. 720 deg"),
    // 87.1 raw unit is not in the manual: 0.1 deg (A-PARAM-1).
    num(87, 1, "Max. position tracking error", PT::UInt16, AC::RW, ST::Config, "0.1 deg", "deg", 0.1, 1, 900,
        10, "6.2", "Position tracking error monitoring", "0.1 .. 90 deg"),
    num(87, 2, "Position tracking error monitoring active", PT::UInt8, AC::RW, ST::Config, "-", "", 1.0, 0, 1,
        1, "6.2", "Position tracking error monitoring", "0: inactive, 1: active"),
    // 6.3 persistent diagnostics (read-only; counters updated by the Device).
    // DE original "Anzahl Drehbewegungen": moves, not revolutions (EN says "rotations").
    num(96, 0, "Number of rotary movements", PT::UInt32, AC::R, ST::PersistentDiag, "1", "1", 1.0, 0, kU32Max, 0,
        "6.3"),
    num(97, 1, "Total operating time", PT::UInt32, AC::R, ST::PersistentDiag, "min", "h", kHoursPerMinute, 0,
        kU32Max, 0, "6.3", "Operating hours counter"),
    num(97, 2, "Operating time with motor switched on", PT::UInt32, AC::R, ST::PersistentDiag, "min", "h",
        kHoursPerMinute, 0, kU32Max, 0, "6.3", "Operating hours counter"),
    num(97, 3, "Operating time with moving motor", PT::UInt32, AC::R, ST::PersistentDiag, "min", "h",
        kHoursPerMinute, 0, kU32Max, 0, "6.3", "Operating hours counter"),
    num(98, 1, "Operating time at maximum temperature", PT::UInt32, AC::R, ST::PersistentDiag, "min", "h",
        kHoursPerMinute, 0, kU32Max, 0, "6.3", "Maximum temperature ever measured"),
    num(98, 2, "Temperature", PT::UInt8, AC::R, ST::PersistentDiag, "0.5 degC", "degC", 0.5, 0, kU8Max, 0,
        "6.3", "Maximum temperature ever measured"),
    num(99, 1, "Operating time at maximum temperature", PT::UInt32, AC::R, ST::PersistentDiag, "min", "h",
        kHoursPerMinute, 0, kU32Max, 0, "6.3", "Maximum temperature (resettable)", "reset: command 160"),
    num(99, 2, "Temperature", PT::UInt8, AC::R, ST::PersistentDiag, "0.5 degC", "degC", 0.5, 0, kU8Max, 0,
        "6.3", "Maximum temperature (resettable)", "reset: command 160"),
    num(100, 0, "Operating time with temperature warning", PT::UInt32, AC::R, ST::PersistentDiag, "min", "h",
        kHoursPerMinute, 0, kU32Max, 0, "6.3", {}, "reset: command 161"),
    // 6.4 volatile diagnostics, SREH specific; 7.2 / 7.3 list the cause codes.
    num(112, 0, "Temperature", PT::UInt8, AC::R, ST::Volatile, "0.5 degC", "degC", 0.5, 0, kU8Max, 0, "6.4"),
    num(113, 0, "Motor voltage", PT::UInt16, AC::R, ST::Volatile, "mV", "V", 0.001, 0, kU16Max, 0, "6.4", {},
        "between pins 2 and 5 of the M12 connector"),
    num(114, 1, "Cause for error bit 7", PT::UInt8, AC::R, ST::Volatile, "-", "", 1.0, 0, kU8Max, 0, "6.4, 7.2",
        "Error causes", "1 internal configuration faulty"),
    num(114, 2, "Cause for error bit 6", PT::UInt8, AC::R, ST::Volatile, "-", "", 1.0, 0, kU8Max, 0, "6.4, 7.2",
        "Error causes", "1 overcurrent, 2 trajectory, 3 state machine, 255 unknown"),
    num(114, 3, "Cause for error bit 5", PT::UInt8, AC::R, ST::Volatile, "-", "", 1.0, 0, kU8Max, 0, "6.4, 7.2",
        "Error causes", "1 overtemperature"),
    num(114, 4, "Cause for error bit 4", PT::UInt8, AC::R, ST::Volatile, "-", "", 1.0, 0, kU8Max, 0, "6.4, 7.2",
        "Error causes", "1 motor voltage too low, 2 too high"),
    num(114, 5, "Cause for error bit 3", PT::UInt8, AC::R, ST::Volatile, "-", "", 1.0, 0, kU8Max, 0, "6.4, 7.2",
        "Error causes", "64 position tracking error"),
    num(114, 6, "Cause for error bit 2", PT::UInt8, AC::R, ST::Volatile, "-", "", 1.0, 0, kU8Max, 0, "6.4, 7.2",
        "Error causes", "1, 2, 4, 5, 6 command errors; 16 link interruption; 17 outputs invalid"),
    num(114, 7, "Cause for error bit 1", PT::UInt8, AC::R, ST::Volatile, "-", "", 1.0, 0, kU8Max, 0, "6.4, 7.2",
        "Error causes", "1 target position, 2 parameter set, 3 relative and shortest path"),
    num(114, 8, "Cause for error bit 0", PT::UInt8, AC::R, ST::Volatile, "-", "", 1.0, 0, kU8Max, 0, "6.4, 7.2",
        "Error causes", "1 settling-timeout"),
    num(115, 1, "Cause for warning bit 7", PT::UInt8, AC::R, ST::Volatile, "-", "", 1.0, 0, kU8Max, 0,
        "6.4, 7.3", "Warning causes", "1 temperature warning"),
    num(115, 2, "Cause for warning bit 6", PT::UInt8, AC::R, ST::Volatile, "-", "", 1.0, 0, kU8Max, 0,
        "6.4, 7.3", "Warning causes", "1 motor voltage too low, 2 too high"),
    num(115, 3, "Cause for warning bit 5", PT::UInt8, AC::R, ST::Volatile, "-", "", 1.0, 0, kU8Max, 0,
        "6.4, 7.3", "Warning causes", "1 position tolerance window left"),
    // 6.5 / 6.4 firmware update profile (manual 9).
    text(17342, 0, "HW ID", PT::String, AC::R, ST::Identification, kHardwareId, 0, "6.5, 9"),
    num(17343, 0, "Boot mode status", PT::UInt8, AC::R, ST::Volatile, "-", "", 1.0, 0, kU8Max, 0, "6.4, 9"),
};

template <std::size_t... N>
constexpr auto concat(const std::array<ParameterEntry, N>&... parts) {
  std::array<ParameterEntry, (N + ...)> out{};
  std::size_t i = 0;
  ((std::copy(parts.begin(), parts.end(), out.begin() + static_cast<std::ptrdiff_t>(i)), i += N), ...);
  return out;
}

// THE table: one row per index/subindex, ascending.
constexpr auto kTable = concat(kHead, motion_set(0), motion_set(1), motion_set(2), motion_set(3), motion_set(4),
                               motion_set(5), motion_set(6), motion_set(7), kTail);

constexpr bool sorted_and_unique() {
  for (std::size_t i = 1; i < kTable.size(); ++i) {
    const auto& a = kTable[i - 1];
    const auto& b = kTable[i];
    if (a.index > b.index || (a.index == b.index && a.subindex >= b.subindex)) return false;
  }
  return true;
}
static_assert(sorted_and_unique(), "parameter table must be sorted by index/subindex without duplicates");

// O(1) row lookup for indices below 128 with subindex 0..8.
constexpr uint16_t kLookupIndices = 128;
constexpr uint8_t kLookupSubs = 9;
constexpr auto kLookup = [] {
  std::array<int16_t, kLookupIndices * kLookupSubs> lut{};
  for (auto& v : lut) v = -1;
  for (std::size_t i = 0; i < kTable.size(); ++i) {
    const auto& row = kTable[i];
    if (row.index < kLookupIndices && row.subindex < kLookupSubs)
      lut[row.index * kLookupSubs + row.subindex] = static_cast<int16_t>(i);
  }
  return lut;
}();
constexpr bool all_rows_in_lookup() {
  for (const auto& row : kTable)
    if (row.index < kLookupIndices && row.subindex >= kLookupSubs) return false;
  return true;
}
static_assert(all_rows_in_lookup(), "subindex beyond the lookup table");

} // namespace

std::span<const ParameterEntry> parameter_table() { return kTable; }
std::size_t parameter_row_count() { return kTable.size(); }

int row_position(uint16_t index, uint8_t subindex) {
  if (index < kLookupIndices) {
    return subindex < kLookupSubs ? kLookup[index * kLookupSubs + subindex] : -1;
  }
  for (std::size_t i = kTable.size(); i-- > 0;) { // the few rows >= 128 are at the end
    if (kTable[i].index < kLookupIndices) break;
    if (kTable[i].index == index && kTable[i].subindex == subindex) return static_cast<int>(i);
  }
  return -1;
}

const ParameterEntry* find_parameter(uint16_t index, uint8_t subindex) {
  const int pos = row_position(index, subindex);
  return pos < 0 ? nullptr : &kTable[static_cast<std::size_t>(pos)];
}

bool is_record(uint16_t index) { return row_position(index, 1) >= 0; }

std::vector<const ParameterEntry*> record_members(uint16_t index) {
  std::vector<const ParameterEntry*> members;
  if (!is_record(index)) return members;
  for (const auto& row : kTable)
    if (row.index == index) members.push_back(&row);
  return members;
}

bool index_exists(uint16_t index) {
  return row_position(index, 0) >= 0 || is_record(index);
}

bool is_numeric(ParamType type) {
  switch (type) {
    case ParamType::UInt8:
    case ParamType::UInt16:
    case ParamType::UInt32:
    case ParamType::Int32:
      return true;
    case ParamType::String:
    case ParamType::OctetString:
    case ParamType::Record:
      return false;
  }
  return false;
}

std::size_t wire_size(ParamType type) {
  switch (type) {
    case ParamType::UInt8: return 1;
    case ParamType::UInt16: return 2;
    case ParamType::UInt32:
    case ParamType::Int32: return 4;
    case ParamType::String:
    case ParamType::OctetString:
    case ParamType::Record: return 0;
  }
  return 0;
}

std::string_view type_name(ParamType type) {
  switch (type) {
    case ParamType::UInt8: return "uint8";
    case ParamType::UInt16: return "uint16";
    case ParamType::UInt32: return "uint32";
    case ParamType::Int32: return "int32";
    case ParamType::String: return "string";
    case ParamType::OctetString: return "OctetString";
    case ParamType::Record: return "record";
  }
  return "?";
}

std::string_view row_type_text(const ParameterEntry& row) {
  return row.type_label.empty() ? type_name(row.type) : row.type_label;
}

std::string_view access_name(Access access) {
  switch (access) {
    case Access::R: return "r";
    case Access::RW: return "rw";
    case Access::W: return "w";
  }
  return "?";
}

std::string_view storage_name(Storage storage) {
  switch (storage) {
    case Storage::Config: return "config";
    case Storage::PersistentDiag: return "persistent";
    case Storage::Volatile: return "volatile";
    case Storage::Identification: return "identification";
    case Storage::Command: return "command";
  }
  return "?";
}

std::vector<uint8_t> encode_number(ParamType type, int64_t raw) {
  const std::size_t n = wire_size(type);
  std::vector<uint8_t> out(n);
  be::write(out, static_cast<uint64_t>(raw));
  return out;
}

int64_t decode_number(ParamType type, std::span<const uint8_t> bytes) {
  const std::size_t n = std::min(wire_size(type), bytes.size());
  const uint64_t bits = be::read(bytes.first(n));
  if (type == ParamType::Int32) return static_cast<int32_t>(static_cast<uint32_t>(bits));
  return static_cast<int64_t>(bits);
}

} // namespace sreh
