#include "serve/http_events.hpp"

#include <algorithm>
#include <chrono>
#include <regex>
#include <vector>

#include <fmt/format.h>

#include "serve/port_api.hpp"

namespace sreh::serve {
namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kKeepAliveEvery = std::chrono::seconds(2);

std::string json_answer(int status, const char* reason, const Json& body, const char* extra = "") {
  const std::string text = body.dump();
  return fmt::format("HTTP/1.1 {} {}\r\nContent-Type: application/json\r\nContent-Length: {}\r\n{}Connection: close\r\n\r\n{}",
                     status, reason, text.size(), extra, text);
}

// The value of header `name` (case-insensitive), "" if absent.
std::string header(const std::string& request, const std::string& name) {
  const auto end = request.find("\r\n\r\n");
  for (std::size_t at = request.find("\r\n") + 2; at < end;) {
    const std::size_t eol = request.find("\r\n", at);
    const std::string line = request.substr(at, eol - at);
    const auto colon = line.find(':');
    if (colon == name.size() &&
        std::equal(name.begin(), name.end(), line.begin(), [](char a, char b) { return std::tolower(a) == std::tolower(b); })) {
      const auto b = line.find_first_not_of(" \t", colon + 1);
      return b == std::string::npos ? "" : line.substr(b, line.find_last_not_of(" \t") - b + 1);
    }
    at = eol + 2;
  }
  return "";
}

class HubEventStream final : public EventStream {
 public:
  HubEventStream(Hub& hub, std::vector<int> ports, uint64_t cursor, std::atomic<int>& count,
                 const std::atomic<bool>& stopping)
      : hub_(hub), ports_(std::move(ports)), cursor_(cursor), count_(count), stopping_(stopping), last_sent_(Clock::now()) {}
  ~HubEventStream() override { count_.fetch_sub(1); }

  bool alive() const override { return hub_.running() && !stopping_.load(); }

  // Every event of the ports up to the hub's counter now, in order: one
  // cursor for all ports (an event counted later is not in a ring yet, so
  // none is skipped).
  std::string next() override {
    const uint64_t upto = hub_.latest_event_seq();
    std::vector<std::pair<int, PortEvent>> got;
    for (int p : ports_)
      for (auto& e : hub_.events_after(p, cursor_, std::chrono::milliseconds(0)))
        if (e.seq <= upto) got.emplace_back(p, std::move(e));
    std::sort(got.begin(), got.end(), [](const auto& a, const auto& b) { return a.second.seq < b.second.seq; });
    std::string out;
    for (const auto& [p, e] : got) {
      const std::string data = e.json.size() > 1 && e.json.front() == '{'
                                   ? fmt::format("{{\"port\":{},{}", p, e.json.substr(1))
                                   : e.json;
      out += fmt::format("id: {}-{}\nevent: {}\ndata: {}\n\n", hub_.run_id(), e.seq, e.type, data);
    }
    cursor_ = std::max(cursor_, upto);
    const auto now = Clock::now();
    if (out.empty() && now - last_sent_ >= kKeepAliveEvery) out = ": keep-alive\n\n";
    if (!out.empty()) last_sent_ = now;
    return out;
  }

 private:
  Hub& hub_;
  std::vector<int> ports_;
  uint64_t cursor_;
  std::atomic<int>& count_;
  const std::atomic<bool>& stopping_;
  Clock::time_point last_sent_;
};

} // namespace

std::optional<FrontAnswer> open_event_stream(Hub& hub, const std::string& request, std::atomic<int>& streams,
                                             const std::atomic<bool>& stopping) {
  static const std::regex line(R"(^GET (/v1/events(\?[^ ]*)?|/v1/ports/([1-9][0-9]?)/events) HTTP/1\.[01]\r\n)");
  std::smatch m;
  if (!std::regex_search(request, m, line)) return std::nullopt;
  FrontAnswer a;
  a.keep_alive = false;
  std::vector<int> ports;
  if (m[3].matched) { // /v1/ports/{p}/events
    const int p = std::stoi(m[3].str());
    if (!hub.valid_port(p)) {
      a.bytes = json_answer(404, "Not Found", Json{{"error", fmt::format("no port {} (ports 1 .. {})", p, hub.port_count())}});
      return a;
    }
    ports.push_back(p);
  } else {
    const std::string query = m[2].matched ? m[2].str().substr(1) : "";
    static const std::regex ports_query(R"(^ports=([1-9][0-9]?(,[1-9][0-9]?)*)$)");
    std::smatch q;
    if (query.empty()) {
      for (int p = 1; p <= hub.port_count(); ++p) ports.push_back(p);
    } else if (std::regex_match(query, q, ports_query)) {
      const std::string list = q[1].str();
      for (std::size_t at = 0; at < list.size();) {
        const auto comma = list.find(',', at);
        const int p = std::stoi(list.substr(at, comma - at));
        if (!hub.valid_port(p)) {
          a.bytes = json_answer(404, "Not Found", Json{{"error", fmt::format("no port {} (ports 1 .. {})", p, hub.port_count())}});
          return a;
        }
        if (std::find(ports.begin(), ports.end(), p) == ports.end()) ports.push_back(p);
        at = comma == std::string::npos ? list.size() : comma + 1;
      }
    } else {
      a.bytes = json_answer(400, "Bad Request", Json{{"error", "events: the query is ports=P[,P...] (e.g. ports=1,3)"}});
      return a;
    }
  }
  if (streams.fetch_add(1) >= kMaxStreams) {
    streams.fetch_sub(1);
    a.bytes = json_answer(503, "Service Unavailable",
                          Json{{"error", fmt::format("at most {} event streams at a time (one per client: "
                                                     "GET /v1/events carries every port)", kMaxStreams)}},
                          "Retry-After: 1\r\n");
    return a;
  }
  // Resuming within this run: from the client's last id; otherwise new events only.
  uint64_t cursor = hub.latest_event_seq();
  const std::string last = header(request, "Last-Event-ID");
  const std::string prefix = hub.run_id() + "-";
  if (last.size() > prefix.size() && last.compare(0, prefix.size(), prefix) == 0 &&
      last.find_first_not_of("0123456789", prefix.size()) == std::string::npos && last.size() - prefix.size() <= 19)
    cursor = std::min<uint64_t>(cursor, std::stoull(last.substr(prefix.size())));
  std::string hello = "retry: 1000\n\n";
  for (int p : ports)
    hello += fmt::format("event: hello\ndata: {}\n\n", hub.with_port(p, [&](Hub::Port& port) { return port_summary(p, port); }).dump());
  a.bytes = "HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\nCache-Control: no-cache\r\nConnection: close\r\n\r\n" + hello;
  a.stream = std::make_shared<HubEventStream>(hub, std::move(ports), cursor, streams, stopping);
  return a;
}

} // namespace sreh::serve
