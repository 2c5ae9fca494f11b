// Modbus TCP front (issue 18, isolation issue 27): one thread, poll() over
// the listening socket and the clients, each with its own receive buffer
// (a slow client only stalls itself), framing in modbus_frame.hpp, the
// register map in modbus_handler.hpp / modbus_map.hpp.
//  - a started frame must be complete within kFrameDeadline, else the
//    connection closes; a client silent for idle_timeout_s is disconnected;
//  - at most max_clients: one more evicts the connection without a completed
//    request for the longest, never one that completed one within 5 s;
//  - a bad MBAP header (protocol id, length) or a PDU whose length does not
//    match its function closes the connection without an answer.
#pragma once
#include <chrono>
#include <string>
#include <vector>

#include "serve/front.hpp"
#include "serve/hub.hpp"

namespace sreh::serve {

struct ModbusOptions {
  std::string host = "127.0.0.1";
  int port = 502;               // 0: the OS picks a free port (see bound_port())
  bool token_set = false;       // with a token, only `writers` may write; everyone may read (ISDU reads too)
  std::vector<std::string> writers; // client IP addresses (as the OS reports them, e.g. 127.0.0.1)
  double idle_timeout_s = 10;
  int max_clients = 32;
};

using ModbusServer = Front<ModbusOptions>;
SREH_SERVE_EXTERN_FRONT(ModbusOptions);
// Instantiated in the .cpp (with its Impl); front.hpp declares the members only, so
// no other file instantiates them (clang refuses an extern template before Impl).

} // namespace sreh::serve
