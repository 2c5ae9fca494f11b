// MQTT front (libmosquitto, optional): publishes each port's process data
// and state on change and at a steady rate, device events as they come, and
// takes commands on topics (docs/serve.md has the topic list):
//   <prefix>/availability                  (retained) "online" / "offline", the bridge's last will
//   <prefix>/port/<p>/availability         (retained) "online" / "offline", a per-port connection's last will
//   <prefix>/port/<p>/processdata          (published, retained; cleared on stop) processdata JSON
//   <prefix>/port/<p>/events               (published) state / device_event
//   <prefix>/port/<p>/processdata/out/set  (command) body as PUT processdata/out
//   <prefix>/port/<p>/faults/set           (command) body as POST faults
//   <prefix>/port/<p>/isdu/request         (command) {"id", "op": "read"|"write", "index", "subindex", "value"|"raw"}
//   <prefix>/port/<p>/isdu/response        (published) {"id", "ok", ...} or {"id", "ok": false, "iolink_error", "message"}
//   <prefix>/errors                        (published) refused commands: {"topic", "error"}
// With a token, every command is signed ("auth", serve/mqtt_auth.hpp) or
// carries it as "token"; nothing serve publishes ever contains it.
#pragma once
#include <memory>
#include <string>

#include "serve/front.hpp"
#include "serve/hub.hpp"

namespace sreh::serve {

struct MqttOptions {
  std::string host = "127.0.0.1";
  int port = 1883;
  std::string prefix = "sreh-twin";
  int interval_ms = 1000; // steady republish; changes go out within 20 ms
  std::string token;
};

using MqttBridge = Front<MqttOptions>;
SREH_SERVE_EXTERN_FRONT(MqttOptions);
// Instantiated in the .cpp (with its Impl); front.hpp declares the members only, so
// no other file instantiates them (clang refuses an extern template before Impl).

} // namespace sreh::serve
