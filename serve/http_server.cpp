#include "serve/http_server.hpp"

#include <httplib.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cerrno>
#include <cstring>
#include <regex>

#include <fmt/format.h>

#include "io/html_page.hpp"
#include "serve/front_impl.hpp"
#include "serve/http_auth.hpp"
#include "serve/http_events.hpp"
#include "serve/http_front.hpp"
#include "serve/listen_socket.hpp"
#include "serve/parameter_catalog.hpp"
#include "serve/port_api.hpp"
#include "serve/web_assets.hpp"

namespace sreh::serve {
namespace {

constexpr int kListenBacklog = 1024;
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
    {"GET", "/v1/ports/{p}", R"(/v1/ports/([1-9]\d?))"},
    {"GET", "/v1/ports/{p}/processdata", R"(/v1/ports/([1-9]\d?)/processdata)"},
    {"PUT", "/v1/ports/{p}/processdata/out", R"(/v1/ports/([1-9]\d?)/processdata/out)"},
    {"GET", "/v1/ports/{p}/parameters/{index}/{subindex}", R"(/v1/ports/([1-9]\d?)/parameters/(\d{1,5})/(\d{1,3}))"},
    {"PUT", "/v1/ports/{p}/parameters/{index}/{subindex}", R"(/v1/ports/([1-9]\d?)/parameters/(\d{1,5})/(\d{1,3}))"},
    {"GET", "/v1/ports/{p}/events", R"(/v1/ports/([1-9]\d?)/events)"},
    {"GET", "/v1/events", "/v1/events"},
    {"GET", "/v1/ports/{p}/faults", R"(/v1/ports/([1-9]\d?)/faults)"},
    {"POST", "/v1/ports/{p}/faults", R"(/v1/ports/([1-9]\d?)/faults)"},
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

// cpp-httplib parses a request and routes it; the connection front
// (http_front.hpp) gives it one whole request read beforehand, so a worker
// never waits for a client.
class Router final : public httplib::Server {
 public:
  using httplib::Server::process_request;
};

// One whole request in, the whole answer collected: nothing here touches the socket.
class BufferStream final : public httplib::Stream {
 public:
  BufferStream(const std::string& in, int fd) : in_(in), fd_(fd) {}
  bool is_readable() const override { return at_ < in_.size(); }
  bool is_writable() const override { return true; }
  ssize_t read(char* ptr, size_t size) override {
    const std::size_t n = std::min(size, in_.size() - at_);
    std::copy_n(in_.data() + at_, n, ptr);
    at_ += n;
    return static_cast<ssize_t>(n);
  }
  ssize_t write(const char* ptr, size_t size) override {
    out.append(ptr, size);
    return static_cast<ssize_t>(size);
  }
  void get_remote_ip_and_port(std::string& ip, int& port) const override { address(getpeername, ip, port); }
  void get_local_ip_and_port(std::string& ip, int& port) const override { address(getsockname, ip, port); }
  socket_t socket() const override { return fd_; }
  std::string out;

 private:
  template <class F>
  void address(F f, std::string& ip, int& port) const {
    sockaddr_storage a{};
    socklen_t len = sizeof a;
    char text[INET6_ADDRSTRLEN] = {};
    port = 0;
    if (f(fd_, reinterpret_cast<sockaddr*>(&a), &len) != 0) return;
    if (a.ss_family == AF_INET) {
      inet_ntop(AF_INET, &reinterpret_cast<sockaddr_in*>(&a)->sin_addr, text, sizeof text);
      port = ntohs(reinterpret_cast<sockaddr_in*>(&a)->sin_port);
    } else if (a.ss_family == AF_INET6) {
      inet_ntop(AF_INET6, &reinterpret_cast<sockaddr_in6*>(&a)->sin6_addr, text, sizeof text);
      port = ntohs(reinterpret_cast<sockaddr_in6*>(&a)->sin6_port);
    }
    ip = text;
  }
  const std::string& in_;
  std::size_t at_ = 0;
  int fd_;
};

template <>
struct Front<HttpOptions>::Impl {
  Hub& hub;
  HttpOptions options;
  Router server;
  int listen_fd = -1;
  std::unique_ptr<HttpFront> front;
  std::atomic<bool> stopping{false};
  std::atomic<int> streams{0};
  std::vector<std::regex> route_patterns; // kRoutes[i].pattern, for 405

  Impl(Hub& h, const HttpOptions& o) : hub(h), options(o) {
    for (const auto& r : kRoutes) route_patterns.emplace_back(r.pattern);
    server.set_payload_max_length(o.max_body_bytes); // larger bodies: 413
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
    listen_fd = listen_tcp(o.host, o.port, "http", kListenBacklog);
    front = std::make_unique<HttpFront>(listen_fd, o.max_body_bytes, [this](const std::string& request, int fd) {
      return serve_one(request, fd);
    });
  }

  ~Impl() {
    stop();
    if (listen_fd >= 0) ::close(listen_fd);
  }

  // One whole request: an event stream (http_events.hpp) or cpp-httplib's routing.
  FrontAnswer serve_one(const std::string& request, int fd) {
    if (auto stream = open_event_stream(hub, request, streams, stopping)) return std::move(*stream);
    BufferStream strm(request, fd);
    bool closed = false;
    server.process_request(strm, false, closed, nullptr);
    FrontAnswer a;
    a.bytes = std::move(strm.out);
    // A request the parser refused leaves the connection in doubt: close it.
    a.keep_alive = !closed && a.bytes.compare(0, 12, "HTTP/1.1 400") != 0 && a.bytes.compare(0, 12, "HTTP/1.1 414") != 0;
    return a;
  }

  // "GET, PUT" for a path some route serves with other methods; "" if none does.
  std::string allowed_methods(const std::string& path) const {
    std::string allow;
    for (std::size_t i = 0; i < route_patterns.size(); ++i)
      if (std::regex_match(path, route_patterns[i]) && allow.find(kRoutes[i].method) == std::string::npos)
        allow += fmt::format("{}{}", allow.empty() ? "" : ", ", kRoutes[i].method);
    return allow;
  }

  // {"1": "cannot write ...", ...}: the ports whose last state write failed.
  Json state_write_errors() {
    Json j = Json::object();
    for (int p = 1; p <= hub.port_count(); ++p)
      if (const std::string e = hub.with_port(p, [](Hub::Port& port) { return port.state_write_error; }); !e.empty())
        j[std::to_string(p)] = e;
    return j;
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
    } catch (const StateWriteFailed& e) { // the state folder cannot take it: not done (issue 40)
      res.set_header("Retry-After", "1");
      send_json(res, 503, Json{{"iolink_error", iolink_error_text(e.code)}, {"message", e.what()}});
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
                            {"realtime_scheduling", s.realtime_scheduling},
                            {"run_id", hub.run_id()},
                            {"state_write_failures", hub.state_write_failures()},
                            {"state_write_errors", state_write_errors()},
                            {"http_connections", front->connections()}});
    }
    if (path.find("events") != std::string::npos) // GET is the front's (http_events.hpp); HEAD lands here
      return send_error(res, 405, "event streams answer GET only");
    const int p = port_from(req, res);
    if (p < 0) return;
    const bool write = method != "GET";
    if (write && !authorised(req, res)) return;
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
      const auto run = [&](Hub::Port& port) -> Json {
        if (path == "/v1/ports/{p}") return port_summary(p, port);
        if (path == "/v1/ports/{p}/processdata") return processdata_json(port);
        if (path == "/v1/ports/{p}/processdata/out") {
          apply_pd_out(port, body);
          return processdata_json(port);
        }
        if (path == "/v1/ports/{p}/faults") return write ? apply_faults(port, body) : faults_json(port);
        if (method == "GET") return read_parameter(port, index, sub);
        return write_parameter(port, index, sub, body);
      };
      // A parameter write or a fault is on disk before its answer, or refused and undone.
      const bool durable = write && path != "/v1/ports/{p}/processdata/out";
      send_json(res, 200, durable ? hub.durable(p, run) : hub.with_port(p, run));
    });
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

  int port() const { return fd_port(listen_fd); }
  void start() { front->start(); }
  void stop() {
    stopping.store(true);
    if (front) front->stop();
  }
};

template class Front<HttpOptions>;

} // namespace sreh::serve
