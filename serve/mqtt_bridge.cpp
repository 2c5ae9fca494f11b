#include "serve/mqtt_bridge.hpp"

#include <mosquitto.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <map>
#include <regex>
#include <set>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "serve/front_impl.hpp"
#include "serve/mqtt_auth.hpp"
#include "serve/port_api.hpp"

namespace sreh::serve {

namespace {
// Signed commands carry "ts" (Unix time in ms); serve takes one only within
// this much of its own clock, and each signature once (issue 40: a captured
// command cannot be replayed). The clocks of the PLC and serve must agree
// to well within it (NTP).
constexpr int64_t kReplayWindow_ms = 30000;
constexpr int kMaxPorts = 16;  // serve's limit: retained topics of ports above --ports are cleared at start
constexpr auto kFlushTimeout = std::chrono::seconds(2);

// One connection per port whose only job is the port's last will: the broker
// publishes "offline" (retained) on <prefix>/port/<p>/availability if serve
// dies without saying goodbye (MQTT has one will per connection).
struct WillClient {
  mosquitto* m = nullptr;
  std::string topic;
  const std::atomic<bool>* running = nullptr;
};
} // namespace

template <>
struct Front<MqttOptions>::Impl {
  Hub& hub;
  MqttOptions options;
  mosquitto* client = nullptr;
  std::vector<WillClient> wills;
  std::mutex flight_mutex;
  std::condition_variable flight_cv;
  std::set<int> in_flight; // message ids not yet acknowledged by the broker
  int subscriptions = 0;   // command topics the broker has acknowledged
  std::atomic<bool> running{false};
  std::thread publisher;
  std::vector<std::string> last_published;
  std::vector<uint64_t> event_cursor;
  std::mutex seen_mutex;
  std::map<std::string, int64_t> seen_signatures; // signature -> its ts, forgotten once outside the window

  Impl(Hub& h, const MqttOptions& o)
      : hub(h), options(o), last_published(static_cast<std::size_t>(h.port_count())),
        event_cursor(static_cast<std::size_t>(h.port_count()), 0) {
    mosquitto_lib_init();
    client = mosquitto_new(nullptr, true, this);
    if (client == nullptr) throw std::runtime_error("mqtt: cannot create a client");
    const std::string bridge_will = options.prefix + "/availability";
    mosquitto_will_set(client, bridge_will.c_str(), 7, "offline", 1, true);
    mosquitto_subscribe_callback_set(client, [](mosquitto*, void* self, int, int, const int*) {
      auto* impl = static_cast<Impl*>(self);
      std::lock_guard lock(impl->flight_mutex);
      ++impl->subscriptions;
      impl->flight_cv.notify_all();
    });
    mosquitto_publish_callback_set(client, [](mosquitto*, void* self, int mid) {
      auto* impl = static_cast<Impl*>(self);
      std::lock_guard lock(impl->flight_mutex);
      impl->in_flight.erase(mid);
      impl->flight_cv.notify_all();
    });
    mosquitto_connect_callback_set(client, [](mosquitto* m, void* self, int rc) {
      if (rc != 0) return;
      auto* impl = static_cast<Impl*>(self);
      impl->subscribe(m);
      // Every (re)connect: the broker may have published the last will meanwhile (issue 40).
      if (impl->running.load()) impl->publish(impl->options.prefix + "/availability", "online", true);
    });
    mosquitto_message_callback_set(client, [](mosquitto*, void* self, const mosquitto_message* msg) {
      static_cast<Impl*>(self)->on_message(msg);
    });
    const int rc = mosquitto_connect(client, o.host.c_str(), o.port, 10);
    if (rc != MOSQ_ERR_SUCCESS) {
      mosquitto_destroy(client);
      mosquitto_lib_cleanup();
      throw std::runtime_error(fmt::format("mqtt: cannot connect to the broker at {}:{}: {}", o.host, o.port,
                                           rc == MOSQ_ERR_ERRNO ? std::string(strerror(errno)) : mosquitto_strerror(rc)));
    }
    try {
      connect_wills();
    } catch (...) {
      for (auto& w : wills) mosquitto_destroy(w.m);
      mosquitto_destroy(client);
      mosquitto_lib_cleanup();
      throw;
    }
  }

  ~Impl() {
    stop();
    for (auto& w : wills) mosquitto_destroy(w.m);
    mosquitto_destroy(client);
    mosquitto_lib_cleanup();
  }

  // The per-port will connections (see WillClient); "online" once connected.
  void connect_wills() {
    wills.reserve(static_cast<std::size_t>(hub.port_count())); // stable addresses: each is its client's user data
    for (int p = 1; p <= hub.port_count(); ++p) {
      WillClient w;
      w.topic = topic(p, "availability");
      w.running = &running;
      w.m = mosquitto_new(nullptr, true, nullptr);
      if (w.m == nullptr) throw std::runtime_error("mqtt: cannot create a client");
      mosquitto_will_set(w.m, w.topic.c_str(), 7, "offline", 1, true);
      mosquitto_connect_callback_set(w.m, [](mosquitto* m, void* self, int rc) { // every reconnect: online again
        const auto* will = static_cast<const WillClient*>(self);
        if (rc == 0 && will != nullptr && will->running->load())
          mosquitto_publish(m, nullptr, will->topic.c_str(), 6, "online", 1, true);
      });
      const int rc = mosquitto_connect(w.m, options.host.c_str(), options.port, 10);
      if (rc != MOSQ_ERR_SUCCESS) {
        mosquitto_destroy(w.m);
        throw std::runtime_error(fmt::format("mqtt: cannot connect to the broker at {}:{}: {}", options.host,
                                             options.port, mosquitto_strerror(rc)));
      }
      wills.push_back(w);
      mosquitto_user_data_set(wills.back().m, &wills.back());
    }
  }

  // The token never leaves serve (issue 27): every payload is checked.
  std::string redact(std::string payload) const {
    if (options.token.empty()) return payload;
    for (auto at = payload.find(options.token); at != std::string::npos; at = payload.find(options.token, at))
      payload.replace(at, options.token.size(), "***");
    return payload;
  }

  // Waits (bounded) until the broker has every message published so far.
  void flush() {
    std::unique_lock lock(flight_mutex);
    flight_cv.wait_for(lock, kFlushTimeout, [this] { return in_flight.empty(); });
  }

  std::string topic(int p, const char* what) const { return fmt::format("{}/port/{}/{}", options.prefix, p, what); }

  void publish(const std::string& t, const std::string& text, bool retain = false) {
    const std::string payload = redact(text);
    int mid = 0;
    std::lock_guard lock(flight_mutex); // the ack cannot overtake the insert
    if (mosquitto_publish(client, &mid, t.c_str(), static_cast<int>(payload.size()), payload.data(), 1, retain) ==
        MOSQ_ERR_SUCCESS)
      in_flight.insert(mid);
  }

  void subscribe(mosquitto* m) {
    for (const char* what : {"processdata/out/set", "faults/set", "isdu/request"}) {
      const std::string t = fmt::format("{}/port/+/{}", options.prefix, what);
      mosquitto_subscribe(m, nullptr, t.c_str(), 1);
    }
  }

  void refuse(const std::string& t, const std::string& why) {
    publish(options.prefix + "/errors", Json{{"topic", t}, {"error", why}}.dump());
  }

  void on_message(const mosquitto_message* msg) {
    const std::string t = msg->topic;
    static const std::regex pattern(R"(^.*/port/(\d{1,3})/(processdata/out/set|faults/set|isdu/request)$)");
    std::smatch m;
    if (!std::regex_match(t, m, pattern)) return;
    const int p = std::stoi(m[1].str());
    const std::string what = m[2].str();
    // A retained command would run again at every start and override what
    // the PLC did since: refused (issue 40).
    if (msg->retain) return refuse(t, "retained command refused (a command runs once: publish it without the retain flag)");
    if (!hub.valid_port(p)) return refuse(t, fmt::format("no port {} (ports 1 .. {})", p, hub.port_count()));
    Json body;
    Json id = nullptr;
    try {
      body = parse_body(std::string(static_cast<const char*>(msg->payload), static_cast<std::size_t>(msg->payloadlen)));
      if (what == "isdu/request") id = body.value("id", Json(nullptr)); // every answer carries it, refusals too
      if (!options.token.empty()) authorise(t, msg, body);
      body.erase("token");
      body.erase("auth");
      body.erase("ts");
      if (what == "processdata/out/set") {
        hub.with_port(p, [&](Hub::Port& port) { apply_pd_out(port, body); });
      } else if (what == "faults/set") {
        hub.durable(p, [&](Hub::Port& port) { apply_faults(port, body); });
      } else {
        isdu_request(p, body, id);
      }
    } catch (const StateWriteFailed& e) {
      if (what == "isdu/request")
        publish(topic(p, "isdu/response"),
                Json{{"id", id}, {"ok", false}, {"iolink_error", iolink_error_text(e.code)}, {"message", e.what()}}.dump());
      else
        refuse(t, e.what());
    } catch (const RequestError& e) {
      if (what == "isdu/request") publish(topic(p, "isdu/response"), Json{{"id", id}, {"ok", false}, {"error", e.what()}}.dump());
      refuse(t, e.what());
    } catch (const IsduRefused& e) {
      publish(topic(p, "isdu/response"),
              Json{{"id", id}, {"ok", false}, {"iolink_error", iolink_error_text(e.code)}, {"message", e.what()}}.dump());
    }
  }

  // With a token: "auth" (signed, the token never on the wire) or "token".
  void authorise(const std::string& t, const mosquitto_message* msg, const Json& body) {
    if (body.contains("auth")) {
      const std::string payload(static_cast<const char*>(msg->payload), static_cast<std::size_t>(msg->payloadlen));
      if (!body["auth"].is_string() || !command_signed(options.token, t, payload, body["auth"].get<std::string>()))
        throw RequestError(403, "wrong signature (auth)");
      check_fresh(body);
      return;
    }
    if (!body.contains("token") || !body["token"].is_string() || body["token"].get<std::string>() != options.token)
      throw RequestError(403, "missing or wrong token (or auth)");
  }

  // A signed command is taken once, and only near its time stamp "ts".
  void check_fresh(const Json& body) {
    if (!body.contains("ts") || !body["ts"].is_number_integer())
      throw RequestError(403, "a signed command needs \"ts\": Unix time in ms (replay protection)");
    const int64_t ts = body["ts"].get<int64_t>();
    const int64_t now = std::chrono::duration_cast<std::chrono::milliseconds>(
                            std::chrono::system_clock::now().time_since_epoch()).count();
    if (ts < now - kReplayWindow_ms || ts > now + kReplayWindow_ms)
      throw RequestError(403, fmt::format("\"ts\" is {} ms from serve's clock (at most {} ms: replayed, or the clocks "
                                          "disagree)", ts - now, kReplayWindow_ms));
    std::lock_guard lock(seen_mutex);
    std::erase_if(seen_signatures, [&](const auto& kv) { return kv.second < now - kReplayWindow_ms; });
    if (!seen_signatures.emplace(body["auth"].get<std::string>(), ts).second)
      throw RequestError(403, "this signed command was taken already (replayed)");
  }

  void isdu_request(int p, Json body, const Json& id) {
    body.erase("id");
    const std::string op = body.value("op", "");
    if (op != "read" && op != "write") throw RequestError(400, "isdu/request: op must be \"read\" or \"write\"");
    const auto number = [&](const char* key, int64_t max) {
      if (!body.contains(key) || !body[key].is_number_integer() || body[key].get<int64_t>() < 0 || body[key].get<int64_t>() > max)
        throw RequestError(400, fmt::format("isdu/request: {} must be an integer 0 .. {}", key, max));
      return body[key].get<int64_t>();
    };
    const auto index = static_cast<uint16_t>(number("index", 0xFFFF));
    const auto sub = static_cast<uint8_t>(body.contains("subindex") ? number("subindex", 0xFF) : 0);
    body.erase("op");
    body.erase("index");
    body.erase("subindex");
    Json answer = op == "read" ? hub.with_port(p, [&](Hub::Port& port) {
      if (!body.empty()) throw RequestError(400, "isdu/request: a read takes only id, op, index, subindex");
      return read_parameter(port, index, sub);
    })
                               : hub.durable(p, [&](Hub::Port& port) { return write_parameter(port, index, sub, body); });
    Json out{{"id", id}, {"ok", true}};
    for (auto& [k, v] : answer.items()) out[k] = v;
    publish(topic(p, "isdu/response"), out.dump());
  }

  void publish_loop() {
    using PublishClock = std::chrono::steady_clock;
    std::vector<PublishClock::time_point> last(static_cast<std::size_t>(hub.port_count()), PublishClock::time_point{});
    while (running.load()) {
      for (int p = 1; p <= hub.port_count(); ++p) {
        const auto i = static_cast<std::size_t>(p - 1);
        const Json pd = hub.with_port(p, [&](Hub::Port& port) { return processdata_json(port); });
        std::string text = pd.dump();
        const auto now = PublishClock::now();
        if (text != last_published[i] || now - last[i] >= std::chrono::milliseconds(options.interval_ms)) {
          publish(topic(p, "processdata"), text, true);
          last_published[i] = std::move(text);
          last[i] = now;
        }
        for (const auto& e : hub.events_after(p, event_cursor[i], std::chrono::milliseconds(0))) {
          event_cursor[i] = e.seq;
          if (e.type == "sample") continue; // the live page's stream; MQTT gets process data instead
          publish(topic(p, "events"), fmt::format("{{\"type\":\"{}\",\"data\":{}}}", e.type, e.json));
        }
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }

  int port() const { return 0; } // a client: it listens nowhere
  void start() {
    if (running.exchange(true)) return;
    for (int p = 1; p <= hub.port_count(); ++p) event_cursor[static_cast<std::size_t>(p - 1)] = hub.latest_seq(p);
    mosquitto_loop_start(client);
    for (auto& w : wills) {
      mosquitto_loop_start(w.m);
      mosquitto_publish(w.m, nullptr, w.topic.c_str(), 6, "online", 1, true);
    }
    publish(options.prefix + "/availability", "online", true);
    // A previous run with more ports left retained topics behind: clear them.
    for (int p = hub.port_count() + 1; p <= kMaxPorts; ++p) {
      publish(topic(p, "processdata"), "", true);
      publish(topic(p, "availability"), "", true);
    }
    publisher = std::thread([this] { publish_loop(); });
    // Taking commands once start() returns (and serve prints its ready line).
    std::unique_lock lock(flight_mutex);
    flight_cv.wait_for(lock, kFlushTimeout, [this] { return subscriptions >= 3; });
  }
  // Retained state says what is true after stop: no process data, offline.
  void stop() {
    if (!running.exchange(false)) return;
    if (publisher.joinable()) publisher.join();
    for (int p = 1; p <= hub.port_count(); ++p) {
      publish(topic(p, "processdata"), "", true); // an empty retained message deletes it
      publish(topic(p, "availability"), "offline", true);
    }
    publish(options.prefix + "/availability", "offline", true);
    flush();
    for (auto& w : wills) {
      mosquitto_disconnect(w.m); // a clean goodbye: the broker drops the will ("offline" is already there)
      mosquitto_loop_stop(w.m, false);
    }
    mosquitto_disconnect(client);
    mosquitto_loop_stop(client, false);
  }
};

template class Front<MqttOptions>;

} // namespace sreh::serve
