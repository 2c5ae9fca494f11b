// Process data codec, manual 2.2 (out, 6 bytes), 2.3 (in, 7 bytes), 2.5
// (position coding). Big-endian as IO-Link transmits multi-byte values.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <variant>

namespace sreh {

inline constexpr std::size_t kPdOutBytes = 6; // manual 2.2
inline constexpr std::size_t kPdInBytes = 7;  // manual 2.3
using PdOutFrame = std::array<uint8_t, kPdOutBytes>;
using PdInFrame = std::array<uint8_t, kPdInBytes>;

// Outgoing process data: PLC -> module (manual 2.2). Where each field sits in
// the frame: kPdOutFields below, the one statement of the layout.
struct ProcessDataOut {
  int32_t target_raw = 0;      // 2^16 counts per revolution (manual 2.5)
  uint8_t parameter_set = 0;   // valid 0..7
  bool shortest_path = false;
  bool relative = false;
  bool set_origin = false;
  bool reset_error = false;
  bool stop = false;
  bool move = false;
  bool motor_on = false;
  bool operator==(const ProcessDataOut&) const = default;
};

// Incoming process data: module -> PLC (manual 2.3); the layout: kPdInFields.
struct ProcessDataIn {
  int32_t position_raw = 0;    // 2^16 counts per revolution (manual 2.5)
  uint8_t error_code = 0;      // bit field (manual 2.4)
  uint8_t warning_code = 0;    // bit field (manual 2.4)
  bool error = false;
  bool warning = false;
  bool done = false;
  bool busy = false;
  bool ready = false;
  bool motor_off = false;
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

// The layout as data (manual 2.2, 2.3): the one place it is stated. Each row
// names a field, its bits and the struct member it maps to; the codec loops
// over the rows, the IODD-like export, serve's decoded views, Python's dicts
// and the scenario keys read the same rows. Bit offsets count from the least
// significant bit of the frame, as IO-Link and the manual's tables do.
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

// A row of ProcessDataOut's or ProcessDataIn's table: a PdField plus the
// member it maps to. Type and bit length follow from the member's type
// (int32 32 bits, uint8 8 bits, bool 1 bit), so a row cannot declare a width
// its member does not have; the variant's alternatives are in PdFieldType's
// order.
template <class Pd>
struct PdFieldOf : PdField {
  using Member = std::variant<int32_t Pd::*, uint8_t Pd::*, bool Pd::*>;
  Member member;

  // Arguments: name, manual name, member, bit offset, manual section
  // [, degrees view name].
  constexpr PdFieldOf(std::string_view id, std::string_view manual, int32_t Pd::*m, unsigned offset,
                      std::string_view where, std::string_view deg = {})
      : PdField{id, manual, PdFieldType::Int32, offset, 32, where, deg}, member(m) {}
  constexpr PdFieldOf(std::string_view id, std::string_view manual, uint8_t Pd::*m, unsigned offset,
                      std::string_view where)
      : PdField{id, manual, PdFieldType::UInt8, offset, 8, where}, member(m) {}
  constexpr PdFieldOf(std::string_view id, std::string_view manual, bool Pd::*m, unsigned offset,
                      std::string_view where)
      : PdField{id, manual, PdFieldType::Bool, offset, 1, where}, member(m) {}
};
using PdOutField = PdFieldOf<ProcessDataOut>;
using PdInField = PdFieldOf<ProcessDataIn>;

inline constexpr std::array<PdOutField, 9> kPdOutFields{{
    {"target_raw", "Target position", &ProcessDataOut::target_raw, 16, "2.2, 2.5", "target_deg"},
    {"parameter_set", "Motion parameter set", &ProcessDataOut::parameter_set, 8, "2.2"},
    {"shortest_path", "Shortest path", &ProcessDataOut::shortest_path, 6, "2.2, 4.3"},
    {"relative", "Relative", &ProcessDataOut::relative, 5, "2.2, 4.2"},
    {"set_origin", "Set origin", &ProcessDataOut::set_origin, 4, "2.2, 4.1"},
    {"reset_error", "Error reset", &ProcessDataOut::reset_error, 3, "2.2"},
    {"stop", "Stop", &ProcessDataOut::stop, 2, "2.2"},
    {"move", "Move", &ProcessDataOut::move, 1, "2.2"},
    {"motor_on", "Motor on", &ProcessDataOut::motor_on, 0, "2.2"},
}};
inline constexpr std::array<PdInField, 9> kPdInFields{{
    {"position_raw", "Actual position", &ProcessDataIn::position_raw, 24, "2.3, 2.5", "position_deg"},
    {"error_code", "Error code", &ProcessDataIn::error_code, 16, "2.3, 2.4"},
    {"warning_code", "Warning code", &ProcessDataIn::warning_code, 8, "2.3, 2.4"},
    {"error", "Error", &ProcessDataIn::error, 5, "2.3"},
    {"warning", "Warning", &ProcessDataIn::warning, 4, "2.3"},
    {"done", "Done", &ProcessDataIn::done, 3, "2.3"},
    {"busy", "Busy", &ProcessDataIn::busy, 2, "2.3"},
    {"ready", "Ready", &ProcessDataIn::ready, 1, "2.3"},
    {"motor_off", "Motor off", &ProcessDataIn::motor_off, 0, "2.3"},
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
