#include "serve/http_server.hpp"

#include <httplib.h>

#include <sys/socket.h>

#include <atomic>
#include <chrono>
#include <cerrno>
#include <cstring>
#include <regex>
#include <thread>

#include <fmt/format.h>

#include "io/html_page.hpp"
#include "serve/front_impl.hpp"
#include "serve/http_auth.hpp"
#include "serve/http_workers.hpp"
#include "serve/parameter_catalog.hpp"
#include "serve/port_api.hpp"
#include "serve/web_assets.hpp"

namespace sreh::serve {
namespace {

constexpr int kMaxStreams = 16;       // concurrent event streams; more get 503 at once
constexpr std::size_t kMaxThreads = 256; // connection threads (http_workers.hpp); plain requests keep > 200
constexpr int kListenBacklog = 256;
constexpr const char* kJsonType = "application/json";

struct Route {
  const char* method;
  const char* path;    // OpenAPI form
  const char* pattern; // httplib regex
};

// One table: what is registered is what --print-routes and the OpenAPI check see.
constexpr Route kRoutes[] = {
    {"GET", "/", "/"},
    {"GET", "/assets/{name}", R"(/assets/([A-Za-z0-9._-]+))"},
    {"GET", "/v1/ports", "/v1/ports"},
    {"GET", "/v1/ports/{p}", R"(/v1/ports/(\d{1,3}))"},
    {"GET", "/v1/ports/{p}/processdata", R"(/v1/ports/(\d{1,3})/processdata)"},
    {"PUT", "/v1/ports/{p}/processdata/out", R"(/v1/ports/(\d{1,3})/processdata/out)"},
    {"GET", "/v1/ports/{p}/parameters/{index}/{subindex}", R"(/v1/ports/(\d{1,3})/parameters/(\d{1,5})/(\d{1,3}))"},
    {"PUT", "/v1/ports/{p}/parameters/{index}/{subindex}", R"(/v1/ports/(\d{1,3})/parameters/(\d{1,5})/(\d{1,3}))"},
    {"GET", "/v1/ports/{p}/events", R"(/v1/ports/(\d{1,3})/events)"},
    {"GET", "/v1/ports/{p}/faults", R"(/v1/ports/(\d{1,3})/faults)"},
    {"POST", "/v1/ports/{p}/faults", R"(/v1/ports/(\d{1,3})/faults)"},
    {"GET", "/v1/stats", "/v1/stats"},
    {"GET", "/v1/parameters", "/v1/parameters"}, // the parameter table (issue 39)
};

void send_json(httplib::Response& res, int status, const Json& j) {
  res.status = status;
  res.set_content(j.dump(), kJsonType);
}

void send_error(httplib::Response& res, int status, const std::string& message) {
  send_json(res, status, Json{{"error", message}});
}

std::string content_type_for(std::string_view name) {
  const auto ends = [&](std::string_view ext) {
    return name.size() >= ext.size() && name.substr(name.size() - ext.size()) == ext;
  };
  if (ends(".js")) return "text/javascript; charset=utf-8";
  if (ends(".css")) return "text/css; charset=utf-8";
  if (ends(".html")) return "text/html; charset=utf-8";
  return "application/octet-stream";
}

// The live page: the one page shell (io/html_page.hpp) around web/live_body.html;
// the reports' look (io::kPageCss, issue 39), then its own (app.css) and
// charts (dygraphs) from /assets.
std::string live_page() {
  static const std::string page = io::html_page("sreh-twin: virtual IO-Link master",
                                                std::string("<style>") + io::kPageCss + "</style>\n" +
                                                "<link rel=\"stylesheet\" href=\"/assets/dygraph.min.css\">\n"
                                                "<link rel=\"stylesheet\" href=\"/assets/app.css\">\n"
                                                "<link rel=\"icon\" href=\"data:,\">\n",
                                                find_web_asset("live_body.html"));
  return page;
}

} // namespace

std::vector<RouteInfo> http_routes() {
  std::vector<RouteInfo> out;
  for (const auto& r : kRoutes) out.push_back({r.method, r.path});
  return out;
}

template <>
struct Front<HttpOptions>::Impl {
  Hub& hub;
  HttpOptions options;
  httplib::Server server;
  int bound = -1;
  std::thread thread;
  std::atomic<bool> stopping{false};
  std::atomic<int> streams{0};

  std::vector<std::regex> route_patterns; // kRoutes[i].pattern, for 405
  int listen_fd = -1;                     // cpp-httplib's listening socket (owned by it)

  Impl(Hub& h, const HttpOptions& o) : hub(h), options(o) {
    for (const auto& r : kRoutes) route_patterns.emplace_back(r.pattern);
    server.new_task_queue = [] { return new ConnectionThreads(kMaxThreads); };
    // SO_REUSEADDR only: cpp-httplib's default adds SO_REUSEPORT, which let a
    // second serve share the port silently (issue 27).
    server.set_socket_options([this](socket_t sock) {
      const int yes = 1;
      setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
      listen_fd = sock;
    });
    server.set_payload_max_length(o.max_body_bytes); // larger bodies: 413
    server.set_read_timeout(2, 0);
    server.set_write_timeout(2, 0);
    server.set_keep_alive_timeout(2);
    server.set_tcp_nodelay(true); // no 40 ms Nagle / delayed-ACK stalls on small answers
    server.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
      std::string what = "internal error";
      try {
        if (ep) std::rethrow_exception(ep);
      } catch (const std::exception& e) {
        what = std::string("internal error: ") + e.what();
      } catch (...) {
      }
      send_error(res, 500, what);
    });
    server.set_error_handler([this](const httplib::Request& req, httplib::Response& res) {
      if (!res.body.empty()) return;
      if (res.status == 404) {
        const std::string allow = allowed_methods(req.path);
        if (!allow.empty()) {
          res.set_header("Allow", allow);
          return send_error(res, 405, fmt::format("{} {}: method not allowed (allowed: {})", req.method, req.path, allow));
        }
        send_error(res, 404, fmt::format("no route {} {}", req.method, req.path));
      }
      else if (res.status == 413) send_error(res, 413, "request body too large");
      else send_error(res, res.status, fmt::format("HTTP {}", res.status));
    });
    register_routes();
    errno = 0;
    bound = o.port == 0 ? server.bind_to_any_port(o.host) : (server.bind_to_port(o.host, o.port) ? o.port : -1);
    if (bound < 0)
      throw std::runtime_error(fmt::format("http: cannot listen on {}:{}: {}", o.host, o.port,
                                           errno == EADDRINUSE ? "address in use"
                                           : errno != 0       ? std::strerror(errno)
                                                              : "cannot bind"));
    // cpp-httplib listens with a backlog of 5: a burst of clients then waits
    // for SYN retries (1 s, 2 s, ...). listen() again only enlarges it.
    if (listen_fd >= 0) ::listen(listen_fd, kListenBacklog);
  }

  // "GET, PUT" for a path some route serves with other methods; "" if none does.
  std::string allowed_methods(const std::string& path) const {
    std::string allow;
    for (std::size_t i = 0; i < route_patterns.size(); ++i)
      if (std::regex_match(path, route_patterns[i]) && allow.find(kRoutes[i].method) == std::string::npos)
        allow += fmt::format("{}{}", allow.empty() ? "" : ", ", kRoutes[i].method);
    return allow;
  }

  // The port number from the path, or a 404 answer.
  int port_from(const httplib::Request& req, httplib::Response& res) {
    const int p = std::stoi(req.matches[1].str());
    if (!hub.valid_port(p)) {
      send_error(res, 404, fmt::format("no port {} (ports 1 .. {})", p, hub.port_count()));
      return -1;
    }
    return p;
  }

  // Writes need "Authorization: Bearer <token>" when a token is configured
  // (the scheme name is case-insensitive, RFC 7235).
  bool authorised(const httplib::Request& req, httplib::Response& res) {
    if (options.token.empty()) return true;
    const std::string auth = req.get_header_value("Authorization");
    if (auth.empty()) {
      res.set_header("WWW-Authenticate", "Bearer");
      send_error(res, 401, "this server requires a bearer token for writes");
      return false;
    }
    if (!bearer_matches(auth, options.token)) {
      send_error(res, 403, "wrong bearer token");
      return false;
    }
    return true;
  }

  // Runs f under the port lock and maps the errors every route shares.
  template <class F>
  void guarded(httplib::Response& res, F&& f) {
    try {
      f();
    } catch (const RequestError& e) {
      send_error(res, e.status, e.what());
    } catch (const IsduRefused& e) {
      send_json(res, http_status_for(e.code), Json{{"iolink_error", iolink_error_text(e.code)}, {"message", e.what()}});
    }
  }

  void handle(const Route& route, const httplib::Request& req, httplib::Response& res) {
    const std::string path = route.path;
    const std::string method = route.method;
    if (path == "/") {
      res.set_content(live_page(), "text/html; charset=utf-8");
      return;
    }
    if (path == "/assets/{name}") {
      const std::string name = req.matches[1].str();
      const auto data = find_web_asset(name);
      if (data.empty()) return send_error(res, 404, "no asset " + name);
      res.set_header("Cache-Control", "max-age=3600");
      res.set_content(std::string(data), content_type_for(name).c_str());
      return;
    }
    if (path == "/v1/ports") {
      Json list = Json::array();
      for (int p = 1; p <= hub.port_count(); ++p) list.push_back(hub.with_port(p, [&](Hub::Port& port) { return port_summary(p, port); }));
      return send_json(res, 200, list);
    }
    if (path == "/v1/parameters") return send_json(res, 200, parameter_catalog());
    if (path == "/v1/stats") {
      const PacingStats s = hub.stats();
      return send_json(res, 200,
                       Json{{"ports", hub.port_count()},
                            {"cycle_s", hub.options().cycle_s},
                            {"speed", hub.options().speed},
                            {"cycles", s.cycles},
                            {"late_cycles", s.late_cycles},
                            {"jitter_p50_us", s.jitter_p50_us},
                            {"jitter_p99_us", s.jitter_p99_us},
                            {"jitter_max_us", s.jitter_max_us},
                            {"sim_time_s", s.sim_time_s},
                            {"wall_time_s", s.wall_time_s},
                            {"busy_fraction", s.busy_fraction},
                            {"realtime_scheduling", s.realtime_scheduling}});
    }
    const int p = port_from(req, res);
    if (p < 0) return;
    const bool write = method != "GET";
    if (write && !authorised(req, res)) return;
    if (path == "/v1/ports/{p}/events") return stream_events(p, req, res);
    guarded(res, [&] {
      Json body;
      if (write) body = parse_body(req.body); // before the lock: bad JSON never touches the twin
      uint16_t index = 0;
      uint8_t sub = 0;
      if (path.find("/parameters/") != std::string::npos) {
        const long i = std::stol(req.matches[2].str()), s = std::stol(req.matches[3].str());
        if (i > 0xFFFF || s > 0xFF) throw RequestError(400, fmt::format("index {} / subindex {}: index is 0 .. 65535, subindex 0 .. 255", i, s));
        index = static_cast<uint16_t>(i);
        sub = static_cast<uint8_t>(s);
      }
      const Json out = hub.with_port(p, [&](Hub::Port& port) -> Json {
        if (path == "/v1/ports/{p}") return port_summary(p, port);
        if (path == "/v1/ports/{p}/processdata") return processdata_json(port);
        if (path == "/v1/ports/{p}/processdata/out") {
          apply_pd_out(port, body);
          return processdata_json(port);
        }
        if (path == "/v1/ports/{p}/faults") return write ? apply_faults(port, body) : faults_json(port);
        if (method == "GET") return read_parameter(port, index, sub);
        return write_parameter(port, index, sub, body);
      });
      if (write) hub.persist(p); // before the answer: an answered write survives a kill
      send_json(res, 200, out);
    });
  }

  // Server-Sent Events: the current state first, then every new event.
  void stream_events(int p, const httplib::Request& req, httplib::Response& res) {
    if (streams.fetch_add(1) >= kMaxStreams) {
      streams.fetch_sub(1);
      res.set_header("Connection", "close"); // the surplus client gives its thread back at once
      res.set_header("Retry-After", "1");
      return send_error(res, 503, fmt::format("at most {} event streams at a time", kMaxStreams));
    }
    uint64_t after = hub.latest_seq(p);
    if (req.has_header("Last-Event-ID")) {
      try {
        after = std::stoull(req.get_header_value("Last-Event-ID"));
      } catch (...) {
      }
    }
    const Json hello = hub.with_port(p, [&](Hub::Port& port) { return port_summary(p, port); });
    res.set_header("Cache-Control", "no-cache");
    auto cursor = std::make_shared<uint64_t>(after);
    auto first = std::make_shared<bool>(true);
    res.set_chunked_content_provider(
        "text/event-stream",
        [this, p, cursor, first, hello](std::size_t, httplib::DataSink& sink) {
          if (stopping.load() || !hub.running()) {
            sink.done();
            return true;
          }
          std::string chunk;
          if (*first) {
            chunk = fmt::format("retry: 1000\nevent: hello\ndata: {}\n\n", hello.dump());
            *first = false;
          }
          for (const auto& e : hub.events_after(p, *cursor, std::chrono::milliseconds(250))) {
            chunk += fmt::format("id: {}\nevent: {}\ndata: {}\n\n", e.seq, e.type, e.json);
            *cursor = e.seq;
          }
          if (chunk.empty()) chunk = ": keep-alive\n\n";
          return sink.write(chunk.data(), chunk.size());
        },
        [this](bool) { streams.fetch_sub(1); });
  }

  void register_routes() {
    for (const auto& route : kRoutes) {
      auto h = [this, &route](const httplib::Request& req, httplib::Response& res) { handle(route, req, res); };
      const std::string m = route.method;
      if (m == "GET") server.Get(route.pattern, h);
      else if (m == "PUT") server.Put(route.pattern, h);
      else if (m == "POST") server.Post(route.pattern, h);
    }
  }

  int port() const { return bound; }
  void start() {
    thread = std::thread([this] { server.listen_after_bind(); });
    // cpp-httplib's stop() does nothing until the listening loop runs: a stop
    // right after start (a signal during start-up) would leave it in accept()
    // for good. Return only once it runs.
    for (int i = 0; i < 5000 && !server.is_running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  void stop() {
    stopping.store(true);
    server.stop();
    if (thread.joinable()) thread.join();
  }
};

template class Front<HttpOptions>;

} // namespace sreh::serve
