#include "serve/opcua_front.hpp"

#include <netdb.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "device_logic/parameter_table.hpp"
#include "device_logic/process_data.hpp"
#include "serve/front_impl.hpp"
#include "serve/opcua_child.hpp"
#include "serve/port_api.hpp"

namespace sreh::serve {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr const char* kUser = "sreh-twin";              // the OPC UA user whose password is the token
constexpr auto kPortEvery = std::chrono::milliseconds(100); // port status and statistics
constexpr int kMaxBackoffS = 30;

std::string type_text(ParamType t) {
  switch (t) {
    case ParamType::UInt8: return "uint8";
    case ParamType::UInt16: return "uint16";
    case ParamType::UInt32: return "uint32";
    case ParamType::Int32: return "int32";
    case ParamType::String: return "string";
    case ParamType::OctetString: return "octets";
    case ParamType::Record: return "record";
  }
  return "octets";
}

std::string access_text(Access a) { return a == Access::R ? "r" : a == Access::RW ? "rw" : "w"; }

// The one parameter table (device_logic/parameter_table), as the front builds its variables from it.
Json params_json() {
  Json rows = Json::array();
  for (const ParameterEntry& r : parameter_table()) {
    rows.push_back(Json{{"index", r.index},
                        {"subindex", r.subindex},
                        {"name", r.name},
                        {"record", r.record_name},
                        {"type", type_text(r.type)},
                        {"access", access_text(r.access)},
                        {"raw_unit", r.raw_unit},
                        {"display_unit", r.display_unit},
                        {"display_scale", r.display_scale},
                        {"min", r.min},
                        {"max", r.max},
                        {"section", r.section},
                        {"notes", r.notes}});
  }
  return rows;
}

// Identification (manual 6.5) as the device answers it: index -> hex.
Json identity_json(Hub::Port& port) {
  Json j = Json::object();
  for (const int index : {13, 16, 17, 18, 19, 20, 21, 22, 23}) {
    const IsduResult r = port.twin.isdu_read(static_cast<uint16_t>(index), 0);
    if (r.ok()) j[std::to_string(index)] = hex_bytes(r.data);
  }
  return j;
}

// A used address fails here, at once, not after the front has loaded its nodesets.
void check_address_free(const std::string& host, int port) {
  if (port == 0) return;
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE;
  addrinfo* res = nullptr;
  if (getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &res) != 0 || res == nullptr)
    throw std::runtime_error(fmt::format("opcua {}:{}: cannot resolve the address", host, port));
  const int fd = socket(res->ai_family, res->ai_socktype | SOCK_CLOEXEC, 0);
  const int one = 1;
  if (fd >= 0) setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one); // as node's listen
  const bool ok = fd >= 0 && bind(fd, res->ai_addr, res->ai_addrlen) == 0;
  const int err = errno;
  if (fd >= 0) close(fd);
  freeaddrinfo(res);
  if (!ok)
    throw std::runtime_error(fmt::format("opcua {}:{}: {}", host, port,
                                         err == EADDRINUSE ? "address in use" : std::strerror(err)));
}

bool device_active(const Hub::Port& port) {
  return port.failure.empty() && port.faults.link_up && port.twin.powered();
}

} // namespace

bool is_loopback_host(const std::string& host) {
  return host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0;
}

std::string opcua_front_dir() {
  std::vector<fs::path> candidates;
  if (const char* env = std::getenv("SREH_TWIN_OPCUA_DIR"); env != nullptr && *env != '\0') candidates.emplace_back(env);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) candidates.push_back(exe.parent_path().parent_path() / "share" / "sreh_twin" / "opcua");
  candidates.emplace_back(SREH_INSTALLED_OPCUA_DIR);
  candidates.emplace_back(SREH_SOURCE_OPCUA_DIR);
  std::string tried;
  for (const fs::path& dir : candidates) {
    if (fs::is_regular_file(dir / "server.js", ec)) {
      if (!fs::is_directory(dir / "node_modules" / "node-opcua", ec))
        throw std::runtime_error(fmt::format("opcua: {} has no node_modules: run `npm ci` there (./setup.sh does)",
                                             dir.string()));
      return dir.lexically_normal().string();
    }
    tried += (tried.empty() ? "" : ", ") + dir.string();
  }
  throw std::runtime_error("opcua: the OPC UA front (server.js) was not found (looked in " + tried +
                           "; set SREH_TWIN_OPCUA_DIR)");
}

template <>
struct Front<OpcuaOptions>::Impl {
  Hub& hub;
  OpcuaOptions options;
  std::string dir;         // server.js
  std::string pki_dir;     // certificates
  bool own_pki = false;    // a temporary folder removed at stop (no --state-dir)
  Json config;
  int port_number = 0;     // where it listens (fixed after the first start, so clients reconnect there)

  std::mutex mutex;        // guards child, ready, fatal, ended
  std::condition_variable cv;
  std::shared_ptr<ChildProcess> child;
  bool ready = false, ended = false;
  std::string fatal;
  std::thread reader, publisher, supervisor;
  std::atomic<bool> running{false};
  std::atomic<bool> stopping{false}; // stop() called: a start in progress gives up
  std::atomic<bool> resync{true}; // a new front: send everything again

  Impl(Hub& h, const OpcuaOptions& o) : hub(h), options(o) {
    if (!is_loopback_host(o.host) && o.token.empty())
      throw std::runtime_error(fmt::format("--opcua {}: an address other than loopback needs --token-file (the "
                                           "password of OPC UA user '{}')", o.host, kUser));
    if (!is_loopback_host(o.host) && o.state_dir.empty())
      throw std::runtime_error(fmt::format("--opcua {}: an address other than loopback needs --state-dir (the "
                                           "server certificate clients trust is kept there)", o.host));
    check_address_free(o.host, o.port);
    dir = opcua_front_dir();
    if (!o.state_dir.empty()) {
      pki_dir = (fs::path(o.state_dir) / "opcua-pki").string();
    } else {
      std::string tmpl = (fs::temp_directory_path() / "sreh-twin-opcua-XXXXXX").string();
      if (mkdtemp(tmpl.data()) == nullptr) throw std::runtime_error("opcua: cannot create a temporary folder");
      pki_dir = tmpl;
      own_pki = true;
    }
    config = make_config();
    port_number = o.port;
    try {
      spawn();
    } catch (...) {
      remove_pki();
      throw;
    }
  }

  ~Impl() {
    stop();
    remove_pki();
  }

  void remove_pki() {
    std::error_code ec;
    if (own_pki) fs::remove_all(pki_dir, ec);
  }

  Json make_config() {
    Json identity = Json::array();
    for (int p = 1; p <= hub.port_count(); ++p) identity.push_back(hub.with_port(p, identity_json));
    return Json{{"t", "config"},
                {"host", options.host},
                {"loopback", is_loopback_host(options.host)},
                {"ports", hub.port_count()},
                {"cycle_ms", hub.options().cycle_s * 1e3},
                {"pki_dir", pki_dir},
                {"user", kUser},
                {"password", options.token.empty() ? Json(nullptr) : Json(options.token)},
                {"vendor_id", 0}, // not in the manual (A-IODD-1)
                {"device_id", 0},
                {"iolink_revision", "1.1"},
                {"min_cycle_time_ms", 2.0}, // manual 1
                {"pd_in_bytes", kPdInBytes},
                {"pd_out_bytes", kPdOutBytes},
                {"min_sampling_ms", 1},
                {"min_publishing_ms", 5},
                {"version", SREH_OPCUA_VERSION},
                {"identity", identity},
                {"params", params_json()}};
  }

  int port() const { return port_number; }

  // Starts a front and waits for its "ready" (throws with its "fatal" message or how it ended).
  void spawn() {
    Json c = config;
    c["port"] = port_number;
    auto ch = std::make_shared<ChildProcess>(std::vector<std::string>{node_program(), "server.js"}, dir);
    {
      std::lock_guard lock(mutex);
      child = ch;
      ready = ended = false;
      fatal.clear();
    }
    if (reader.joinable()) reader.join();
    reader = std::thread([this, ch] { read_loop(ch); });
    ch->write_line(c.dump());
    std::unique_lock lock(mutex);
    const bool done = cv.wait_for(lock, std::chrono::seconds(options.startup_timeout_s),
                                  [&] { return ready || ended || stopping.load(); });
    if (ready) {
      resync = true;
      return;
    }
    std::string why = !fatal.empty() ? fatal : done ? "it ended before listening" : "no answer in time";
    lock.unlock();
    const int status = ch->stop(2000);
    if (fatal.empty() && WIFEXITED(status) && WEXITSTATUS(status) == 127)
      why = fmt::format("cannot run '{}' (Node.js; ./setup.sh installs it, $SREH_TWIN_NODE names another)", node_program());
    if (reader.joinable()) reader.join();
    throw std::runtime_error(fmt::format("opcua {}:{}: {} ({})", options.host, port_number, why,
                                         describe_wait_status(status)));
  }

  static std::string node_program() {
    const char* env = std::getenv("SREH_TWIN_NODE");
    return env != nullptr && *env != '\0' ? env : "node";
  }

  void read_loop(std::shared_ptr<ChildProcess> ch) {
    while (auto line = ch->read_line()) {
      Json m;
      try {
        m = Json::parse(*line);
      } catch (const std::exception&) {
        std::cerr << "sreh-twin serve: opcua front: " << *line << "\n"; // not the channel's: pass it on
        continue;
      }
      const std::string t = m.value("t", "");
      if (t == "req") {
        ch->write_line(answer(m).dump());
      } else if (t == "ready") {
        std::lock_guard lock(mutex);
        port_number = m.value("port", port_number);
        ready = true;
        cv.notify_all();
      } else if (t == "fatal") {
        std::lock_guard lock(mutex);
        fatal = m.value("message", "failed");
      }
    }
    std::lock_guard lock(mutex);
    ended = true;
    cv.notify_all();
  }

  // One request of the front, between two master cycles (the port lock).
  Json answer(const Json& m) {
    Json reply{{"t", "reply"}, {"id", m.value("id", 0)}};
    const int p = m.value("p", 0);
    const std::string op = m.value("op", "");
    if (!hub.valid_port(p)) {
      reply["ok"] = false;
      reply["error"] = fmt::format("no port {}", p);
      return reply;
    }
    const auto body = [&](Hub::Port& port) {
      if (op == "pd_out") {
        apply_pd_out(port, Json{{"raw", m.at("raw").get<std::string>()}});
        reply["ok"] = true;
        return;
      }
      if (!device_active(port)) { // OPC 30120 7.1.4.1: Status -2
        reply["ok"] = false;
        reply["not_active"] = true;
        return;
      }
      const auto index = m.at("index").get<uint16_t>();
      const auto sub = m.at("sub").get<uint8_t>();
      // The same ISDU access as every front (0x8020 while a Data Storage restore is owed).
      const IsduResult r = op == "isdu_write"
                               ? port_isdu_write(port, index, sub, parse_hex(m.at("data").get<std::string>(), "data"))
                               : port_isdu_read(port, index, sub);
      reply["ok"] = r.ok();
      if (r.ok()) reply["data"] = hex_bytes(r.data);
      else reply["iolink_error"] = r.error;
    };
    try {
      // A write is on disk before its answer leaves, or refused with the
      // device unchanged (issue 40: Hub::durable).
      if (op == "isdu_write") hub.durable(p, body);
      else hub.with_port(p, body);
    } catch (const StateWriteFailed& e) {
      reply["ok"] = false;
      reply["iolink_error"] = e.code;
      reply.erase("data");
    } catch (const std::exception& e) { // a malformed request (RequestError, JSON)
      reply["ok"] = false;
      reply["error"] = e.what();
    }
    return reply;
  }

  std::shared_ptr<ChildProcess> current() {
    std::lock_guard lock(mutex);
    return ready ? child : nullptr;
  }

  // Every master cycle: process data that changed; every 100 ms the port
  // state; device events as the hub logs them.
  void publish_loop() {
    const int n = hub.port_count();
    const auto period = std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(hub.options().cycle_s / hub.options().speed));
    std::vector<std::string> last_pd(static_cast<std::size_t>(n)), last_port(static_cast<std::size_t>(n));
    std::vector<uint64_t> cursor(static_cast<std::size_t>(n));
    for (int p = 1; p <= n; ++p) cursor[static_cast<std::size_t>(p - 1)] = hub.latest_seq(p);
    auto next = Clock::now();
    auto next_port = next;
    while (running.load()) {
      next += period;
      std::this_thread::sleep_until(next);
      const auto ch = current();
      if (!ch) continue;
      if (resync.exchange(false)) {
        for (auto& s : last_pd) s.clear();
        for (auto& s : last_port) s.clear();
      }
      const bool port_due = Clock::now() >= next_port;
      if (port_due) next_port = Clock::now() + kPortEvery;
      for (int p = 1; p <= n; ++p) {
        const auto i = static_cast<std::size_t>(p - 1);
        Json pd, st;
        hub.with_port(p, [&](Hub::Port& port) {
          const bool in_valid = port.faults.link_up && port.twin.device().powered();
          pd = Json{{"t", "pd"}, {"p", p}, {"in", hex_bytes(encode(port.twin.pd_in()))}, {"in_valid", in_valid},
                    {"out", hex_bytes(encode(port.twin.pd_out()))}, {"out_valid", port.outputs_valid}};
          if (port_due)
            st = Json{{"t", "port"}, {"p", p}, {"link_up", port.faults.link_up}, {"powered", port.twin.powered()},
                      {"failure", !port.failure.empty()}, {"cycles", port.twin.cycles()},
                      {"device_replacements", port.faults.device_replacements}};
        });
        std::string text = pd.dump();
        if (text != last_pd[i]) {
          // When the master saw it: the front's SourceTimestamp (wall clock, ms since 1970).
          pd["ts"] = std::chrono::duration<double, std::milli>(std::chrono::system_clock::now().time_since_epoch()).count();
          if (ch->write_line(pd.dump())) last_pd[i] = std::move(text);
        }
        if (port_due) {
          std::string s = st.dump();
          if (s != last_port[i] && ch->write_line(s)) last_port[i] = std::move(s);
          for (const PortEvent& e : hub.events_after(p, cursor[i], std::chrono::milliseconds(0))) {
            cursor[i] = e.seq;
            if (e.type != "device_event") continue;
            Json ev = Json::parse(e.json);
            ev["t"] = "event";
            ev["p"] = p;
            ch->write_line(ev.dump());
          }
        }
      }
    }
  }

  // A front that ended while serve runs is reported and started again.
  void supervise_loop() {
    int backoff_s = 1;
    while (running.load()) {
      std::shared_ptr<ChildProcess> ch;
      {
        std::unique_lock lock(mutex);
        cv.wait(lock, [&] { return ended || !running.load(); });
        if (!running.load()) return;
        ch = child;
      }
      const int status = ch->stop(1000);
      std::cerr << fmt::format("sreh-twin serve: the OPC UA front stopped ({}); restarting it in {} s\n",
                               describe_wait_status(status), backoff_s);
      {
        std::unique_lock lock(mutex);
        cv.wait_for(lock, std::chrono::seconds(backoff_s), [&] { return !running.load(); });
        if (!running.load()) return;
      }
      try {
        spawn();
        std::cerr << fmt::format("sreh-twin serve: the OPC UA front is back on {}:{}\n", options.host, port_number);
        backoff_s = 1;
      } catch (const std::exception& e) {
        std::cerr << "sreh-twin serve: restarting the OPC UA front failed: " << e.what() << "\n";
        backoff_s = std::min(kMaxBackoffS, backoff_s * 2);
        std::lock_guard lock(mutex);
        ended = true; // try again
      }
    }
  }

  void start() {
    if (running.exchange(true)) return;
    publisher = std::thread([this] { publish_loop(); });
    supervisor = std::thread([this] { supervise_loop(); });
  }

  void stop() {
    stopping = true;
    running = false;
    {
      std::lock_guard lock(mutex);
      cv.notify_all();
    }
    if (supervisor.joinable()) supervisor.join();
    if (publisher.joinable()) publisher.join();
    std::shared_ptr<ChildProcess> ch;
    {
      std::lock_guard lock(mutex);
      ch = child;
    }
    if (ch) {
      ch->write_line(R"({"t":"stop"})");
      ch->stop(5000);
    }
    if (reader.joinable()) reader.join();
  }
};

template class Front<OpcuaOptions>;

} // namespace sreh::serve
