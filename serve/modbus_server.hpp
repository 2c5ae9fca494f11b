// Modbus TCP front (libmodbus): one thread, select() over the listening
// socket and up to 32 clients; the register map is modbus_map.hpp. A client
// that sends a malformed frame is disconnected; the server goes on.
#pragma once
#include <atomic>
#include <memory>
#include <string>
#include <thread>

#include "serve/front.hpp"
#include "serve/hub.hpp"

namespace sreh::serve {

struct ModbusOptions {
  std::string host = "127.0.0.1";
  int port = 502;          // 0: the OS picks a free port (see bound_port())
  bool writes_allowed = true; // false with a token: Modbus carries none, so it is read-only
};

using ModbusServer = Front<ModbusOptions>;
extern template class Front<ModbusOptions>;

} // namespace sreh::serve
