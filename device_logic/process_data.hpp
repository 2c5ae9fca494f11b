// Process data codec, manual 2.2 (out, 6 bytes), 2.3 (in, 7 bytes), 2.5
// (position coding). Big-endian as IO-Link transmits multi-byte values.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <string_view>

namespace sreh {

inline constexpr std::size_t kPdOutBytes = 6; // manual 2.2
inline constexpr std::size_t kPdInBytes = 7;  // manual 2.3
using PdOutFrame = std::array<uint8_t, kPdOutBytes>;
using PdInFrame = std::array<uint8_t, kPdInBytes>;

// Outgoing process data: PLC -> module (manual 2.2).
struct ProcessDataOut {
  int32_t target_raw = 0;      // bits 47..16, 2^16 counts per revolution
  uint8_t parameter_set = 0;   // bits 15..8, valid 0..7
  bool shortest_path = false;  // bit 6
  bool relative = false;       // bit 5
  bool set_origin = false;     // bit 4
  bool reset_error = false;    // bit 3
  bool stop = false;           // bit 2
  bool move = false;           // bit 1
  bool motor_on = false;       // bit 0
  bool operator==(const ProcessDataOut&) const = default;
};

// Incoming process data: module -> PLC (manual 2.3).
struct ProcessDataIn {
  int32_t position_raw = 0;    // bits 55..24
  uint8_t error_code = 0;      // bits 23..16, bit field (manual 2.4)
  uint8_t warning_code = 0;    // bits 15..8, bit field (manual 2.4)
  bool error = false;          // bit 5
  bool warning = false;        // bit 4
  bool done = false;           // bit 3
  bool busy = false;           // bit 2
  bool ready = false;          // bit 1
  bool motor_off = false;      // bit 0
  bool operator==(const ProcessDataIn&) const = default;
};

PdOutFrame encode(const ProcessDataOut& pd);
PdInFrame encode(const ProcessDataIn& pd);
ProcessDataOut decode_out(const PdOutFrame& frame);
ProcessDataIn decode_in(const PdInFrame& frame);

// From bytes of unknown length, as a master or a file hands them over: a frame
// of the wrong length throws std::invalid_argument naming both lengths.
ProcessDataOut decode_out(std::span<const uint8_t> bytes);
ProcessDataIn decode_in(std::span<const uint8_t> bytes);

// The layout as data (manual 2.2, 2.3), for descriptions of the device (the
// IODD-like export, serve's decoded views). Bit offsets count from the least
// significant bit of the frame, as IO-Link and the manual's tables do; a test
// checks each field against encode().
enum class PdFieldType { Int32, UInt8, Bool };
struct PdField {
  std::string_view name;     // the scenario / process-data field name
  std::string_view manual_name;
  PdFieldType type;
  unsigned bit_offset;
  unsigned bit_length;
  std::string_view section;
  // The position fields' degrees view (manual 2.5: 2^16 counts per
  // revolution), named next to the raw one in every decoded view; "" for
  // the others. One vocabulary: `<what>_raw` the wire counts, `<what>_deg`.
  std::string_view deg_name = {};
};
inline constexpr std::array<PdField, 9> kPdOutFields{{
    {"target_raw", "Target position", PdFieldType::Int32, 16, 32, "2.2, 2.5", "target_deg"},
    {"parameter_set", "Motion parameter set", PdFieldType::UInt8, 8, 8, "2.2"},
    {"shortest_path", "Shortest path", PdFieldType::Bool, 6, 1, "2.2, 4.3"},
    {"relative", "Relative", PdFieldType::Bool, 5, 1, "2.2, 4.2"},
    {"set_origin", "Set origin", PdFieldType::Bool, 4, 1, "2.2, 4.1"},
    {"reset_error", "Error reset", PdFieldType::Bool, 3, 1, "2.2"},
    {"stop", "Stop", PdFieldType::Bool, 2, 1, "2.2"},
    {"move", "Move", PdFieldType::Bool, 1, 1, "2.2"},
    {"motor_on", "Motor on", PdFieldType::Bool, 0, 1, "2.2"},
}};
inline constexpr std::array<PdField, 9> kPdInFields{{
    {"position_raw", "Actual position", PdFieldType::Int32, 24, 32, "2.3, 2.5", "position_deg"},
    {"error_code", "Error code", PdFieldType::UInt8, 16, 8, "2.3, 2.4"},
    {"warning_code", "Warning code", PdFieldType::UInt8, 8, 8, "2.3, 2.4"},
    {"error", "Error", PdFieldType::Bool, 5, 1, "2.3"},
    {"warning", "Warning", PdFieldType::Bool, 4, 1, "2.3"},
    {"done", "Done", PdFieldType::Bool, 3, 1, "2.3"},
    {"busy", "Busy", PdFieldType::Bool, 2, 1, "2.3"},
    {"ready", "Ready", PdFieldType::Bool, 1, 1, "2.3"},
    {"motor_off", "Motor off", PdFieldType::Bool, 0, 1, "2.3"},
}};

// One field of a frame read through its row: the bits from bit_offset (from
// the frame's least significant bit) on, Int32 sign-extended, Bool 0 / 1.
// The decoded views (serve's JSON, Python's dicts) are built from the rows
// with it, so they cannot list a field or a bit differently. `frame` must
// be the field table's frame (6 octets out, 7 in).
int64_t pd_field_value(std::span<const uint8_t> frame, const PdField& field);

// Manual 2.5: the int32 position is the low 32 bits of the position in 2^16
// counts per revolution; beyond +-2^15 revolutions it overflows (wraps).
constexpr int32_t wrap_wire_position(int64_t wire_counts) {
  return static_cast<int32_t>(static_cast<uint32_t>(static_cast<uint64_t>(wire_counts) & 0xFFFFFFFFu));
}

} // namespace sreh
