// The Modbus TCP register map of the virtual master (docs/modbus-map.md),
// modelled on common IO-Link masters' maps: per port a block of 1000
// holding registers at port * 1000 with status, process data in/out, an
// acyclic ISDU request/response channel and the pending events. Registers
// are 0-based, bytes big-endian within a register (high byte first), as the
// manual's process data bytes (manual 2.2, 2.3).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "serve/port_api.hpp"

namespace sreh::serve::modbus {

inline constexpr int kPortBlock = 1000;  // port p's registers: p * 1000 ..
// Global block at 0.
inline constexpr int kMapVersion = 0;    // R: layout version (1)
inline constexpr int kPortCount = 1;     // R: number of ports
inline constexpr int kCycle100us = 2;    // R: master cycle in 0.1 ms
inline constexpr int kGlobalCount = 3;
// Offsets inside a port block.
inline constexpr int kStatus = 0;        // R: bit 0 device communicating (PD in valid), bit 1 PD out valid, bit 2 port failed
inline constexpr int kPdIn = 1;          // R: 4 registers, 7 octets + 1 pad octet (manual 2.3)
inline constexpr int kPdInCount = 4;
inline constexpr int kPdOut = 10;        // RW: 3 registers, 6 octets (manual 2.2)
inline constexpr int kPdOutCount = 3;
inline constexpr int kPdOutValid = 13;   // RW: 1 valid, 0 invalid (manual 5)
inline constexpr int kState = 20;        // R: twin extra: state 0 MotorOff .. 5 ErrorOff (manual 3.1)
inline constexpr int kLed = 21;          // R: twin extra: LED band colour 0 off .. 7 violet
inline constexpr int kIsduCommand = 100; // RW: writing 1 (read) or 2 (write) runs the request
inline constexpr int kIsduIndex = 101;
inline constexpr int kIsduSubindex = 102;
inline constexpr int kIsduLength = 103;  // octets of data for a write, 0 .. 232
inline constexpr int kIsduData = 104;    // 116 registers (232 octets)
inline constexpr int kIsduDataCount = 116;
inline constexpr int kIsduRequestCount = kIsduData + kIsduDataCount - kIsduCommand; // 120
inline constexpr int kRespSequence = 300;// R: +1 for every completed request
inline constexpr int kRespStatus = 301;  // R: 0 none yet, 1 ok, 2 refused
inline constexpr int kRespError = 302;   // R: IO-Link error code (0x80xx), 0 if ok
inline constexpr int kRespLength = 303;  // R: octets of answer data
inline constexpr int kRespData = 304;    // R: 116 registers
inline constexpr int kRespCount = kRespData + kIsduDataCount - kRespSequence; // 120
inline constexpr int kDeviceStatus = 500;// R: index 36 (0 OK .. 4 failure)
inline constexpr int kEventCount = 501;  // R: pending events (index 37 entries), at most 16
inline constexpr int kEventChanges = 502;// R: +1 whenever the pending set changes
inline constexpr int kEvents = 503;      // R: 16 x (qualifier, event code)
inline constexpr int kEventSlots = 16;
inline constexpr int kPortUsed = kEvents + 2 * kEventSlots; // registers after this read 0

inline int port_base(int p) { return p * kPortBlock; }
inline int register_count(int ports) { return (ports + 1) * kPortBlock; }

// A client connection's ISDU window on one port (issue 27: per connection,
// so two PLCs on one port never see each other's requests or answers).
struct PortRegisters {
  std::vector<uint16_t> request = std::vector<uint16_t>(kIsduRequestCount, 0);
  std::vector<uint16_t> response = std::vector<uint16_t>(kRespCount, 0);
};

// What the map keeps per port for every client: the pending events last seen.
struct EventTracker {
  std::vector<uint8_t> last_events; // index 37 as last seen
  uint16_t event_changes = 0;
};

// Fills a port's block (kPortBlock registers at `block`) from the twin and
// the connection's ISDU window; the caller holds the port lock.
void fill_port(uint16_t* block, Hub::Port& port, const PortRegisters& regs, EventTracker& events);
void fill_global(uint16_t* regs, int ports, double cycle_s);

// Whether [offset, offset + count) of a port block may be written.
bool writable(int offset, int count);
// Whether a write only touches the connection's own ISDU window and runs no
// ISDU write (allowed without write rights: an ISDU read is a read).
bool read_only_request(int offset, const std::vector<uint16_t>& values);
// Validates a write before it is applied: "" if fine, else why not (the
// server answers exception 03, illegal data value).
std::string check_write(int offset, const std::vector<uint16_t>& values, const uint16_t* block);
// Applies registers written at [offset, offset + count) of the block (already
// holding the new values) to the twin; runs an ISDU request when the command
// register was written. True if that was an ISDU write (to be made durable).
bool apply_write(uint16_t* block, int offset, int count, Hub::Port& port, PortRegisters& regs);
// The ISDU write just answered could not be saved (rolled back): the
// response says refused with `code` (issue 40).
void refuse_isdu(PortRegisters& regs, uint16_t code);

// `serve --print-modbus-map --json`
Json map_json(int ports);

} // namespace sreh::serve::modbus
