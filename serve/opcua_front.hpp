// OPC UA front (issue 38; docs/opcua.md): the virtual master as OPC 30120
// (OPC UA for IO-Link) describes it, served by a Node.js process with
// node-opcua (serve/opcua/server.js) that serve starts, feeds and supervises.
// Channel: JSON lines over the child's stdin/stdout. serve sends the
// configuration (ports, identification, the parameter table), then process
// data whenever a master cycle changed it, port state and the device's
// IO-Link events; the front sends ISDU and process-data-out requests, each
// answered. Constructed = listening (the front said "ready"), else
// std::runtime_error naming why; a front that dies later is reported on
// stderr and restarted (1 s, doubling up to 30 s) until stop().
#pragma once
#include <string>

#include "serve/front.hpp"
#include "serve/hub.hpp"

namespace sreh::serve {

struct OpcuaOptions {
  std::string host = "127.0.0.1";
  int port = 4840;          // 0: any free port
  std::string token;        // --token-file: the password of user "sreh-twin"; anonymous sessions then only read
  std::string state_dir;    // --state-dir: the server certificate is kept in DIR/opcua-pki
  int startup_timeout_s = 180; // loading the nodesets takes seconds on a busy machine
};

using OpcuaFront = Front<OpcuaOptions>;
SREH_SERVE_EXTERN_FRONT(OpcuaOptions);

// 127.0.0.0/8, ::1 or "localhost": security None is offered only there.
bool is_loopback_host(const std::string& host);

// The folder holding server.js and its node_modules: $SREH_TWIN_OPCUA_DIR,
// <program folder>/../share/sreh_twin/opcua (installed), the install prefix,
// the source tree (a build folder). Throws std::runtime_error naming them.
std::string opcua_front_dir();

} // namespace sreh::serve
