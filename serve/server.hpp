// `sreh-twin serve` (issue 18): a virtual IO-Link master. Builds one twin per
// port, starts the pacing thread and the Modbus TCP, HTTP and (optional) MQTT
// fronts, prints where they listen as one JSON line on stdout, and runs
// until SIGINT/SIGTERM (or --duration-s), then stops cleanly (exit 0).
#pragma once
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace sreh::serve {

struct Endpoint {
  std::string host;
  int port = 0;
};

// "HOST:PORT" or "[V6]:PORT"; throws std::invalid_argument naming `option`.
Endpoint parse_endpoint(const std::string& text, const std::string& option);

struct ServeOptions {
  int ports = 1;
  Endpoint modbus{"127.0.0.1", 5020};
  Endpoint http{"127.0.0.1", 8080};
  std::optional<Endpoint> mqtt;
  std::optional<Endpoint> opcua;          // OPC UA (OPC 30120) front, a Node.js process (serve/opcua_front.hpp)
  std::string mqtt_prefix = "sreh-twin";
  int mqtt_interval_ms = 1000;
  std::map<int, std::string> port_config; // port -> scenario-style YAML (device, load, world, sim)
  double speed = 1.0;
  double master_cycle_ms = 2.0;
  int rt_priority = 0;                    // > 0: SCHED_FIFO for the pacing thread (needs CAP_SYS_NICE)
  std::string token_file;
  std::string save_nvm_dir;               // on shutdown: DIR/port<p>.nvm
  std::string state_dir;                  // NV memory and flange kept across restarts (serve/state_dir.hpp)
  double modbus_idle_timeout_s = 10;      // a Modbus client silent this long is disconnected
  std::vector<std::string> modbus_writers; // with a token: client addresses that may write over Modbus
  double duration_s = 0;                  // > 0: stop by itself after this wall time
  std::string model;                      // --model FILE: model card overrides for every port (issue 25)
};

// Throws std::invalid_argument (bad option values, unreadable files: exit 2);
// returns the exit code.
// Exit 4: stopped, but the last write of the state folder failed (issue 40).
inline constexpr int kExitStateNotSaved = 4;
int run_serve(const ServeOptions& options, std::ostream& out, std::ostream& err);

} // namespace sreh::serve
