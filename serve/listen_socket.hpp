// The listening sockets of the Modbus and HTTP fronts.
#pragma once
#include <string>

namespace sreh::serve {

// Bound and listening (non-blocking, close-on-exec), SO_REUSEADDR only (no
// SO_REUSEPORT: a second server on the same port must fail, issue 27).
// Throws std::runtime_error "<what>: cannot listen on HOST:PORT: <reason>".
int listen_tcp(const std::string& host, int port, const char* what, int backlog);
int fd_port(int fd); // the local port of a socket, -1 if unknown

} // namespace sreh::serve
