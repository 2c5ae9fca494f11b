// One Modbus request against the register map (docs/modbus-map.md): FC 3
// reads, FC 6 / 16 writes, FC 23 write-then-read in one request; every port
// touched is accessed under its lock, between two IO-Link cycles. No I/O
// here (serve/modbus_server.cpp does that), so it can be fuzzed.
#pragma once
#include <cstdint>
#include <set>
#include <span>
#include <vector>

#include "serve/hub.hpp"
#include "serve/modbus_map.hpp"

namespace sreh::serve::modbus {

// What one client connection owns: its ISDU window on every port, from its
// first write to that window on (before that it sees the port's last
// request and answer, whoever made them: one-shot tools such as mbpoll
// write the request in one connection and read the answer in the next).
struct Session {
  explicit Session(int ports) : windows(static_cast<std::size_t>(ports)), own(static_cast<std::size_t>(ports), false) {}
  std::vector<PortRegisters> windows;
  std::vector<bool> own; // windows[i] in use
  bool may_write = true; // false: only reads and ISDU read requests (a token is set, the client is not listed)
};

// Shared by all connections of one server, per port: events last seen and
// the last ISDU request and answer of any connection.
struct PortShared {
  EventTracker events;
  PortRegisters last_isdu;
};
using EventTrackers = std::vector<PortShared>;

struct Outcome {
  std::vector<uint8_t> pdu;     // the answer PDU (an exception: function | 0x80, code)
};

// `pdu` has passed pdu_length_matches().
Outcome handle(Hub& hub, Session& session, EventTrackers& events, std::span<const uint8_t> pdu);

} // namespace sreh::serve::modbus
