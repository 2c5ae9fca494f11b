// Modbus TCP front (libmodbus): one thread, select() over the listening
// socket and up to 32 clients; the register map is modbus_map.hpp. A client
// that sends a malformed frame is disconnected; the server goes on.
#pragma once
#include <atomic>
#include <memory>
#include <string>
#include <thread>

#include "serve/hub.hpp"

namespace sreh::serve {

struct ModbusOptions {
  std::string host = "127.0.0.1";
  int port = 502;          // 0: the OS picks a free port (see bound_port())
  bool writes_allowed = true; // false with a token: Modbus carries none, so it is read-only
};

class ModbusServer {
 public:
  ModbusServer(Hub& hub, const ModbusOptions& options); // binds; throws std::runtime_error naming the address
  ~ModbusServer();
  ModbusServer(const ModbusServer&) = delete;
  ModbusServer& operator=(const ModbusServer&) = delete;
  int bound_port() const;
  void start();
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace sreh::serve
