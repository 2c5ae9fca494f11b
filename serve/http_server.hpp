// HTTP/JSON front (cpp-httplib): the /v1 API of docs/api/openapi.yaml, the
// event stream (Server-Sent Events) and the live page at /. Writes need the
// bearer token when one is configured (401 without, 403 wrong); reads stay open.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "serve/front.hpp"
#include "serve/hub.hpp"

namespace sreh::serve {

struct HttpOptions {
  std::string host = "127.0.0.1";
  int port = 8080;                    // 0: the OS picks (bound_port())
  std::string token;                  // empty: no token required
  std::size_t max_body_bytes = 64 * 1024;
};

struct RouteInfo {
  const char* method;
  const char* path; // OpenAPI form, e.g. /v1/ports/{p}/processdata
};
// Every route the server serves (checked against docs/api/openapi.yaml in CI).
std::vector<RouteInfo> http_routes();

using HttpServer = Front<HttpOptions>;
SREH_SERVE_EXTERN_FRONT(HttpOptions);
// Instantiated in the .cpp (with its Impl); front.hpp declares the members only, so
// no other file instantiates them (clang refuses an extern template before Impl).

} // namespace sreh::serve
