// `sreh-twin serve`: a virtual IO-Link master real PLC clients drive over
// Modbus TCP, HTTP/JSON and MQTT (issue 18; docs/modbus-map.md,
// docs/api/openapi.yaml). `--print-modbus-map --json` / `--print-routes
// --json` print the contracts and exit without binding anything.
#include <iostream>
#include <memory>
#include <regex>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "scenarios/scenario.hpp"
#include "serve/http_server.hpp"
#include "serve/modbus_map.hpp"
#include "serve/server.hpp"
#include "tools/command.hpp"

namespace sreh::tools {
namespace {

// serve's own exit codes (docs/serve.md says the same; a CTest compares them).
constexpr const char* kServeExitCodes =
    "Exit codes: 0 stopped cleanly (SIGINT, SIGTERM or --duration-s), 2 bad input (an option, a file, a corrupt "
    "state file, an address in use; one line on stderr, nothing bound), 3 internal error (a bug: please report), "
    "4 stopped, but the state folder did not take everything (stderr names what was not saved).";

struct ServeArgs {
  serve::ServeOptions options;
  std::string modbus = "127.0.0.1:5020";
  std::string http = "127.0.0.1:8080";
  std::string mqtt;
  std::string opcua;
  std::vector<std::string> port_config;
  bool print_map = false;
  bool print_routes = false;
  bool json = false;
};

int serve_command(ServeArgs& a) {
  if (a.print_map) {
    const auto map = serve::modbus::map_json(a.options.ports);
    std::cout << (a.json ? map.dump() : map.dump(2)) << "\n";
    return 0;
  }
  if (a.print_routes) {
    nlohmann::json routes = nlohmann::json::array();
    for (const auto& r : serve::http_routes()) routes.push_back({{"method", r.method}, {"path", r.path}});
    std::cout << (a.json ? routes.dump() : routes.dump(2)) << "\n";
    return 0;
  }
  try {
    a.options.modbus = serve::parse_endpoint(a.modbus, "--modbus");
    a.options.http = serve::parse_endpoint(a.http, "--http");
    if (!a.mqtt.empty()) a.options.mqtt = serve::parse_endpoint(a.mqtt, "--mqtt");
    if (!a.opcua.empty()) a.options.opcua = serve::parse_endpoint(a.opcua, "--opcua");
    static const std::regex pc(R"(^(\d{1,2})=(.+)$)");
    for (const auto& item : a.port_config) {
      std::smatch m;
      if (!std::regex_match(item, m, pc))
        throw std::invalid_argument(fmt::format("--port-config '{}': expected PORT=FILE, e.g. 2=load.yaml", item));
      a.options.port_config[std::stoi(m[1].str())] = m[2].str();
    }
    return serve::run_serve(a.options, std::cout, std::cerr);
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  } catch (const ScenarioError& e) {
    throw InputError(e.what());
  }
}

} // namespace

SREH_REGISTER_COMMAND(70, [](CLI::App& app, int& exit_code) {
  auto a = std::make_shared<ServeArgs>();
  CLI::App* cmd = app.add_subcommand("serve", "Virtual IO-Link master: one twin per port, paced to the wall clock, "
                                              "driven over Modbus TCP, HTTP/JSON (+ live page) and MQTT");
  cmd->add_option("--ports", a->options.ports, "Master ports, one twin each (1 .. 16)")->default_val(1);
  cmd->add_option("--modbus", a->modbus, "Modbus TCP listen address HOST:PORT (PORT 0: any free port)")
      ->default_val("127.0.0.1:5020");
  cmd->add_option("--http", a->http, "HTTP listen address HOST:PORT (PORT 0: any free port)")->default_val("127.0.0.1:8080");
  cmd->add_option("--mqtt", a->mqtt, "MQTT broker HOST:PORT to publish to and take commands from (optional)");
  cmd->add_option("--opcua", a->opcua,
                  "OPC UA (OPC 30120, IO-Link) listen address HOST:PORT, e.g. 127.0.0.1:4840 (PORT 0: any free "
                  "port); other than loopback needs --token-file and --state-dir (docs/opcua.md)");
  cmd->add_option("--mqtt-prefix", a->options.mqtt_prefix, "MQTT topic prefix")->default_val("sreh-twin");
  cmd->add_option("--mqtt-interval-ms", a->options.mqtt_interval_ms, "MQTT republish interval (changes go at once)")
      ->default_val(1000)->check(CLI::Range(20, 3600000));
  cmd->add_option("--port-config", a->port_config,
                  "PORT=FILE: a scenario-style YAML (device, load, world, sim) for that port; "
                  "default factory-new, no load");
  cmd->add_option("--speed", a->options.speed, "Simulated seconds per wall-clock second (0.01 .. 100)")->default_val(1.0);
  cmd->add_option("--master-cycle-ms", a->options.master_cycle_ms, "IO-Link master cycle in ms (multiple of 0.1)")
      ->default_val(2.0);
  cmd->add_option("--rt-priority", a->options.rt_priority,
                  "Run the pacing thread SCHED_FIFO at this priority (1 .. 99; needs CAP_SYS_NICE; 0: normal)")
      ->default_val(0);
  cmd->add_option("--token-file", a->options.token_file,
                  "File holding a bearer token every write must carry (HTTP Authorization, MQTT \"token\"); "
                  "Modbus TCP writes only from --modbus-writers; the file must not be group/world-writable");
  cmd->add_option("--save-nvm-dir", a->options.save_nvm_dir,
                  "On shutdown, save each port's non-volatile memory as DIR/port<P>.nvm (see --state-dir)");
  cmd->add_option("--state-dir", a->options.state_dir,
                  "Keep each port's non-volatile memory and flange angle in DIR across restarts (written when "
                  "they change; missing files: factory-new; the same command line for every run)");
  cmd->add_option("--modbus-idle-timeout-s", a->options.modbus_idle_timeout_s,
                  "Disconnect a Modbus client silent this long")
      ->default_val(10.0)->check(CLI::Range(0.1, 3600.0));
  cmd->add_option("--modbus-writers", a->options.modbus_writers,
                  "With --token-file: client IP addresses allowed to write over Modbus (comma-separated); "
                  "others may read, ISDU reads included")
      ->delimiter(',');
  cmd->add_option("--model", a->options.model,
                  "Model card overrides for every port (YAML as `sreh-twin model show` prints): the module's constants");
  cmd->add_option("--duration-s", a->options.duration_s, "Stop by itself after this many wall-clock seconds")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--print-modbus-map", a->print_map, "Print the Modbus register map and exit (binds nothing)");
  cmd->add_flag("--print-routes", a->print_routes, "Print the HTTP routes and exit (binds nothing)");
  cmd->add_flag("--json", a->json, "With --print-*: compact JSON on one line");
  cmd->footer(kServeExitCodes);
  cmd->callback([a, &exit_code] { exit_code = serve_command(*a); });
});

} // namespace sreh::tools
