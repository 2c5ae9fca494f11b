// The connection front of the HTTP server (issue 40): one thread with
// epoll reads every connection's request whole (request line, headers,
// body) under a deadline before a worker sees it, and writes every answer
// without blocking, so slow or silent clients cost a buffer each, never a
// worker: hundreds of them trickling bytes from the PLC's own address
// leave the workers free for the PLC's requests.
//  - a request must be complete within kRequestDeadline of its first octet
//    (else the connection closes); a connection without a byte for
//    kIdleTimeout (also between keep-alive requests) closes;
//  - at most kMaxConnections: one more evicts the connection that has been
//    waiting for its request the longest (never one being served or streaming);
//  - headers over kMaxHeaderBytes: 431, a body over max_body_bytes: 413,
//    a chunked request body: 411, a bad Content-Length: 400 (then close);
//  - an answer not taken by the client within kWriteDeadline closes the
//    connection; an event stream whose client falls behind by more than
//    kMaxStreamBacklog octets is closed.
// The workers (a few threads) answer through Serve; an event stream is an
// EventStream polled every kStreamPoll by one thread.
#pragma once
#include <chrono>
#include <functional>
#include <memory>
#include <string>

namespace sreh::serve {

// A long-lived answer (Server-Sent Events): next() gives the text to send
// now ("" if nothing); false from alive() ends it.
class EventStream {
 public:
  virtual ~EventStream() = default;
  virtual std::string next() = 0;
  virtual bool alive() const = 0;
};

struct FrontAnswer {
  std::string bytes;                   // the whole answer (status line, headers, body)
  bool keep_alive = true;              // false: close once sent
  std::shared_ptr<EventStream> stream; // set: the connection streams after `bytes`
};

class HttpFront {
 public:
  static constexpr auto kRequestDeadline = std::chrono::seconds(5);
  static constexpr auto kIdleTimeout = std::chrono::seconds(2);
  static constexpr auto kWriteDeadline = std::chrono::seconds(5);
  static constexpr auto kStreamPoll = std::chrono::milliseconds(100);
  static constexpr std::size_t kMaxConnections = 2048;
  static constexpr std::size_t kMaxHeaderBytes = 16 * 1024;
  static constexpr std::size_t kMaxStreamBacklog = 1 << 20;
  static constexpr int kWorkers = 4;

  // One whole request (exactly its octets) and the client's socket (for
  // its addresses only) -> the answer. Called on a worker thread.
  using Serve = std::function<FrontAnswer(const std::string& request, int fd)>;

  // listen_fd: bound and listening (non-blocking is set here); owned by the caller.
  HttpFront(int listen_fd, std::size_t max_body_bytes, Serve serve);
  ~HttpFront();
  HttpFront(const HttpFront&) = delete;
  HttpFront& operator=(const HttpFront&) = delete;

  void start();
  void stop(); // closes every connection; idempotent
  std::size_t connections() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace sreh::serve
