// Server-Sent Events of the HTTP front (issue 40): GET /v1/events[?ports=1,3]
// (one stream per client for any number of ports) and the per-port
// GET /v1/ports/{p}/events. First a `hello` per port (the port summary),
// then every event; every event's data carries "port", every id is
// "<run id>-<n>": a client resuming with the id of this run gets what it
// missed, one with an id of another run (serve restarted) starts over.
// At most kMaxStreams at a time (per connection, whatever its ports); the
// surplus gets 503 at once.
#pragma once
#include <atomic>
#include <optional>
#include <string>

#include "serve/http_front.hpp"
#include "serve/hub.hpp"

namespace sreh::serve {

inline constexpr int kMaxStreams = 16;

// `request`: one whole HTTP request. Not an event-stream GET: nullopt.
// Otherwise the answer: the stream, or a refusal (400, 404, 503).
std::optional<FrontAnswer> open_event_stream(Hub& hub, const std::string& request, std::atomic<int>& streams,
                                             const std::atomic<bool>& stopping);

} // namespace sreh::serve
