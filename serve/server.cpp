#include "serve/server.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "device_logic/units.hpp"
#include "io/atomic_file.hpp"
#include "io/interrupt.hpp"
#include "twin/model_card.hpp"
#include "scenarios/runner.hpp"
#include "scenarios/scenario_parser.hpp"
#include "serve/http_server.hpp"
#include "serve/modbus_server.hpp"
#include "serve/mqtt_bridge.hpp"
#include "serve/opcua_front.hpp"
#include "serve/port_api.hpp"
#include "serve/shutdown.hpp"
#include "serve/state_dir.hpp"
#include "twin/plant.hpp"

#include <sys/stat.h>

namespace sreh::serve {
namespace {

namespace fs = std::filesystem;

std::string slurp(const std::string& path, const std::string& what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(fmt::format("{}: cannot read '{}'", what, path));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

// A port configuration is a scenario file's world: device, load, world, sim
// (its steps, if any, are not run). Parsed by the scenario parser, so the
// same keys and the same FILE:LINE messages apply.
Scenario read_port_config(const std::string& path) {
  std::string text = slurp(path, "--port-config");
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw std::invalid_argument(fmt::format("{}:{}:{}: {}", path, e.mark.line + 1, e.mark.column + 1, e.msg));
  }
  // name and steps are optional here (appended, so line numbers stay right)
  if (root.IsMap() && !root["name"]) text += "\nname: port configuration\n";
  if (root.IsMap() && !root["steps"]) text += "\nsteps:\n  - wait_s: 0\n";
  const std::string dir = fs::path(path).parent_path().string();
  return parse_scenario_text(text, path, dir);
}

std::string endpoint_text(const std::string& host, int port) {
  return host.find(':') != std::string::npos ? fmt::format("[{}]:{}", host, port) : fmt::format("{}:{}", host, port);
}

} // namespace

Endpoint parse_endpoint(const std::string& text, const std::string& option) {
  std::string host, port_text;
  if (!text.empty() && text.front() == '[') {
    const auto close = text.find(']');
    if (close == std::string::npos || close + 1 >= text.size() || text[close + 1] != ':')
      throw std::invalid_argument(fmt::format("{} '{}': expected [IPV6]:PORT", option, text));
    host = text.substr(1, close - 1);
    port_text = text.substr(close + 2);
  } else {
    const auto colon = text.rfind(':');
    if (colon == std::string::npos || colon == 0)
      throw std::invalid_argument(fmt::format("{} '{}': expected HOST:PORT, e.g. 127.0.0.1:5020", option, text));
    host = text.substr(0, colon);
    port_text = text.substr(colon + 1);
  }
  if (port_text.empty() || port_text.size() > 5 || port_text.find_first_not_of("0123456789") != std::string::npos ||
      std::stoi(port_text) > 65535)
    throw std::invalid_argument(fmt::format("{} '{}': port must be 0 .. 65535 (0: any free port)", option, text));
  return Endpoint{host, std::stoi(port_text)};
}

namespace {

// Every option checked before anything starts; returns the token (or "").
std::string check_options(const ServeOptions& o) {
  if (o.ports < 1 || o.ports > 16) throw std::invalid_argument(fmt::format("--ports {}: 1 .. 16", o.ports));
  if (!(o.speed >= 0.01 && o.speed <= 100)) throw std::invalid_argument(fmt::format("--speed {}: 0.01 .. 100", o.speed));
  if (!(o.master_cycle_ms >= 0.4 && o.master_cycle_ms <= 100))
    throw std::invalid_argument(fmt::format("--master-cycle-ms {}: 0.4 .. 100", o.master_cycle_ms));
  for (const auto& [p, file] : o.port_config)
    if (p < 1 || p > o.ports) throw std::invalid_argument(fmt::format("--port-config {}={}: no port {} (--ports {})", p, file, p, o.ports));
  if (!o.save_nvm_dir.empty() && !fs::is_directory(o.save_nvm_dir))
    throw std::invalid_argument(fmt::format("--save-nvm-dir '{}': folder does not exist", o.save_nvm_dir));
  std::string token;
  if (!o.token_file.empty()) {
    struct stat st{};
    if (::stat(o.token_file.c_str(), &st) == 0 && (st.st_mode & (S_IWGRP | S_IWOTH)) != 0)
      throw std::invalid_argument(fmt::format("--token-file '{}': writable by group or others (mode {:03o}); "
                                              "chmod go-w it", o.token_file, st.st_mode & 0777));
    token = trim(slurp(o.token_file, "--token-file"));
    if (token.empty()) throw std::invalid_argument(fmt::format("--token-file '{}': the file is empty", o.token_file));
    if (token.find_first_of(" \t\r\n") != std::string::npos)
      throw std::invalid_argument(fmt::format("--token-file '{}': the token contains whitespace", o.token_file));
  }
  return token;
}

// Ports: factory-new without a load unless configured; the port files read
// into `scenarios` (their start-up writes come later).
std::unique_ptr<Hub> make_hub(const ServeOptions& o, const std::vector<PortState>& kept, std::vector<Scenario>& scenarios) {
  std::vector<TwinConfig> configs;
  for (int p = 1; p <= o.ports; ++p) {
    TwinConfig c;
    try {
      c.module = load_module_model(o.model); // issue 25: the model card with --model's overrides
    } catch (const ModelCardError& e) {
      throw std::invalid_argument(fmt::format("--model: {}", e.what()));
    }
    if (const auto it = o.port_config.find(p); it != o.port_config.end()) {
      Scenario& s = scenarios[static_cast<std::size_t>(p - 1)];
      s = read_port_config(it->second);
      try {
        apply_command_line_model(s, o.model); // over the port file's own `model:`
      } catch (const ScenarioError& e) {
        throw std::invalid_argument(e.what());
      }
      c = make_twin_config(s);
    }
    c.cycle_s = o.master_cycle_ms * 1e-3;
    if (const auto& nvm = kept[static_cast<std::size_t>(p - 1)].nvm) c.nvm_image = *nvm; // newer than a port config's
    configs.push_back(c);
  }
  HubOptions hub_options;
  hub_options.cycle_s = o.master_cycle_ms * 1e-3;
  hub_options.speed = o.speed;
  if (o.rt_priority < 0 || o.rt_priority > 99) throw std::invalid_argument(fmt::format("--rt-priority {}: 0 .. 99", o.rt_priority));
  hub_options.rt_priority = o.rt_priority;
  try {
    return std::make_unique<Hub>(configs, hub_options);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format("--master-cycle-ms {}: {}", o.master_cycle_ms, e.what()));
  }
}

// What the ports kept through the last stop, and what their masters write
// at start-up.
void bring_up_ports(Hub& hub, int ports, const std::vector<PortState>& kept, const std::vector<Scenario>& scenarios) {
  // A restart is a power cycle (manual 4.1): the flange is where it was and
  // the device reads it from its multiturn encoder at power-on.
  for (int p = 1; p <= ports; ++p) {
    if (const auto angle = kept[static_cast<std::size_t>(p - 1)].flange_angle_deg) {
      hub.with_port(p, [&](Hub::Port& port) {
        port.twin.power_off();
        port.twin.turn_flange(*angle - rad_to_deg(port.twin.plant().angle_rad()), 0.0);
        port.twin.power_on();
      });
    }
  }
  // Start-up writes of the port configurations (device.isdu), as a master's parameter server would.
  for (int p = 1; p <= ports; ++p) {
    const Scenario& s = scenarios[static_cast<std::size_t>(p - 1)];
    for (std::size_t i = 0; i < s.device.isdu.size(); ++i) {
      const auto& w = s.device.isdu[i];
      const IsduResult r = hub.with_port(p, [&](Hub::Port& port) { return port.twin.isdu_write(w.index, w.subindex, w.data); });
      if (!r.ok())
        throw std::invalid_argument(fmt::format("{}:{}: device.isdu[{}]: index {}.{} = {} refused with {} ({})", s.file,
                                                w.loc.line, i + 1, w.index, w.subindex, w.value_text,
                                                iolink_error_text(r.error), iolink_error_name(r.error)));
    }
  }
  // Data Storage at the master (manual 8): the backup kept, or a first upload.
  for (int p = 1; p <= ports; ++p)
    hub.with_port(p, [&](Hub::Port& port) {
      const PortState& k = kept[static_cast<std::size_t>(p - 1)];
      port.ds_backup = k.ds;
      port.ds_download_pending = k.ds && k.ds_download_owed;
      port.fresh_module = !k.nvm; // matters only beside a backup, i.e. with --state-dir
    });
  hub.ds_startup();
  // The module's start-up (manual 4.1, A-LINK-3) and a Data Storage download
  // owed, before any client can ask: the first answer is already right (issue 40).
  hub.start_up_ports();
}

// The network fronts (serve/front.hpp), bound but not started.
struct Fronts {
  std::unique_ptr<ModbusServer> modbus;
  std::unique_ptr<HttpServer> http;
  std::unique_ptr<MqttBridge> mqtt;
  std::unique_ptr<OpcuaFront> opcua;
};

Fronts make_fronts(Hub& hub, const ServeOptions& o, const std::string& token) {
  ModbusOptions mo;
  mo.host = o.modbus.host;
  mo.port = o.modbus.port;
  mo.token_set = !token.empty();
  mo.writers = o.modbus_writers;
  mo.idle_timeout_s = o.modbus_idle_timeout_s;
  HttpOptions ho;
  ho.host = o.http.host;
  ho.port = o.http.port;
  ho.token = token;
  Fronts f;
  try {
    f.modbus = std::make_unique<ModbusServer>(hub, mo);
    f.http = std::make_unique<HttpServer>(hub, ho);
    if (o.mqtt) {
      MqttOptions mq;
      mq.host = o.mqtt->host;
      mq.port = o.mqtt->port;
      mq.prefix = o.mqtt_prefix;
      mq.interval_ms = o.mqtt_interval_ms;
      mq.token = token;
      f.mqtt = std::make_unique<MqttBridge>(hub, mq);
    }
    if (o.opcua) {
      OpcuaOptions op;
      op.host = o.opcua->host;
      op.port = o.opcua->port;
      op.token = token;
      op.state_dir = o.state_dir;
      f.opcua = std::make_unique<OpcuaFront>(hub, op);
    }
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());
  }
  return f;
}

// Until a signal, or --duration-s; returns the signal, if one came.
std::optional<int> wait_for_stop(double duration_s) {
  const auto start = std::chrono::steady_clock::now();
  std::optional<int> sig;
  while (!sig) {
    sig = wait_for_shutdown_signal(std::chrono::milliseconds(200));
    if (duration_s > 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >= duration_s)
      break;
  }
  return sig;
}

void save_nvm_images(Hub& hub, int ports, const std::string& dir, std::ostream& err) {
  for (int p = 1; p <= ports; ++p) {
    const auto image = hub.with_port(p, [](Hub::Port& port) { return port.twin.save_nvm(); });
    const std::string path = (fs::path(dir) / fmt::format("port{}.nvm", p)).string();
    io::write_file_atomic(path, [&](std::ostream& f) {
      f.write(reinterpret_cast<const char*>(image.data()), static_cast<std::streamsize>(image.size()));
    });
    err << "sreh-twin serve: saved " << path << "\n";
  }
}

} // namespace

int run_serve(const ServeOptions& o, std::ostream& out, std::ostream& err) {
  const std::string token = check_options(o);

  // --state-dir: what each module kept through the last stop (a power cycle).
  std::unique_ptr<StateDir> state;
  std::vector<PortState> kept(static_cast<std::size_t>(o.ports));
  if (!o.state_dir.empty()) {
    state = std::make_unique<StateDir>(o.state_dir, o.ports);
    for (int p = 1; p <= o.ports; ++p) kept[static_cast<std::size_t>(p - 1)] = state->load(p);
  }
  std::vector<Scenario> scenarios(static_cast<std::size_t>(o.ports));
  const std::unique_ptr<Hub> hub = make_hub(o, kept, scenarios);
  bring_up_ports(*hub, o.ports, kept, scenarios);

  block_shutdown_signals(); // before any thread starts, so only sigtimedwait sees them
  // A signal before that went to the batch commands' handler (io/interrupt):
  // stop now, cleanly, or the twins' cycles would throw io::Interrupted.
  if (io::interrupt_signal() != 0) return 0;
  Fronts fronts = make_fronts(*hub, o, token);
  if (state) { // bound: from here on the state folder is written (exit 2 before leaves it alone)
    hub->set_state_dir(state.get());
    for (int p = 1; p <= o.ports; ++p) hub->persist(p); // the files exist from the first start on
  }
  hub->start();
  fronts.modbus->start();
  fronts.http->start();
  if (fronts.mqtt) fronts.mqtt->start();
  if (fronts.opcua) fronts.opcua->start();

  Json ready{{"ports", o.ports},
             {"modbus", endpoint_text(o.modbus.host, fronts.modbus->bound_port())},
             {"http", endpoint_text(o.http.host, fronts.http->bound_port())},
             {"mqtt", o.mqtt ? Json(endpoint_text(o.mqtt->host, o.mqtt->port)) : Json(nullptr)},
             {"opcua", fronts.opcua ? Json(endpoint_text(o.opcua->host, fronts.opcua->bound_port())) : Json(nullptr)},
             {"speed", o.speed},
             {"master_cycle_ms", o.master_cycle_ms}};
  if (o.rt_priority > 0) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20)); // the pacing thread has asked by now
    if (!hub->stats().realtime_scheduling)
      err << "sreh-twin serve: warning: SCHED_FIFO refused (needs CAP_SYS_NICE); pacing with normal scheduling\n";
  }
  out << ready.dump() << std::endl; // one line: where to connect (ports chosen by the OS included)
  // The same for a person (issue 39): the page to open. A wildcard address
  // is reachable on this machine as localhost.
  const bool wildcard = o.http.host == "0.0.0.0" || o.http.host == "::" || o.http.host.empty();
  err << fmt::format("sreh-twin serve: open http://{}/ for the live page (HTTP API /v1/..., Modbus TCP {}{})\n",
                     endpoint_text(wildcard ? "127.0.0.1" : o.http.host, fronts.http->bound_port()),
                     endpoint_text(o.modbus.host, fronts.modbus->bound_port()),
                     wildcard ? "; listening on every interface: use this machine's name from elsewhere" : "");

  const std::optional<int> sig = wait_for_stop(o.duration_s);
  // Fronts first (no new requests), then the clock.
  if (fronts.opcua) fronts.opcua->stop();
  if (fronts.mqtt) fronts.mqtt->stop();
  fronts.http->stop();
  fronts.modbus->stop();
  hub->stop();
  const PacingStats s = hub->stats();
  err << fmt::format("sreh-twin serve: stopped{} after {} cycles ({:.1f} s simulated, {:.1f} s wall); cycle start "
                     "jitter p50 {:.0f} us, p99 {:.0f} us, max {:.0f} us; {} late cycles\n",
                     sig ? fmt::format(" on signal {}", *sig) : "", s.cycles, s.sim_time_s, s.wall_time_s,
                     s.jitter_p50_us, s.jitter_p99_us, s.jitter_max_us, s.late_cycles);
  if (!o.save_nvm_dir.empty()) save_nvm_images(*hub, o.ports, o.save_nvm_dir, err);
  if (state && !hub->state_saved()) {
    err << "sreh-twin serve: the state folder " << o.state_dir << " did not take everything at stop (see above)\n";
    return kExitStateNotSaved;
  }
  return 0;
}

} // namespace sreh::serve
