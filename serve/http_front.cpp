#include "serve/http_front.hpp"

#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include <fmt/format.h>

namespace sreh::serve {
namespace {

using Clock = std::chrono::steady_clock;

bool iequals_prefix(std::string_view line, std::string_view name) {
  if (line.size() < name.size()) return false;
  for (std::size_t i = 0; i < name.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(line[i])) != std::tolower(static_cast<unsigned char>(name[i])))
      return false;
  return true;
}

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string_view::npos) return "";
  return std::string(s.substr(b, s.find_last_not_of(" \t\r") - b + 1));
}

// An answer the front gives itself (the request never reaches a worker); the connection closes.
std::string refusal(int status, const char* reason, const std::string& message) {
  const std::string body = fmt::format("{{\"error\":\"{}\"}}", message);
  return fmt::format("HTTP/1.1 {} {}\r\nContent-Type: application/json\r\nContent-Length: {}\r\nConnection: close\r\n\r\n{}",
                     status, reason, body.size(), body);
}

enum class Phase { Reading, Working, Writing, Streaming };

struct Conn {
  uint64_t id = 0;
  int fd = -1;
  Phase phase = Phase::Reading;
  std::string in, out;
  std::size_t out_at = 0;
  Clock::time_point last_byte, request_start, write_start;
  bool keep_alive = true;
  bool sent_continue = false;
  bool peer_closed = false;  // the client closed its side (or the socket failed)
  bool write_failed = false;
  std::shared_ptr<EventStream> stream;
  uint32_t armed = 0; // epoll events registered (0: not registered)
};

struct Job {
  uint64_t id;
  int fd;
  std::string request;
};

struct Done {
  uint64_t id;
  FrontAnswer answer;
};

struct StreamText {
  uint64_t id;
  std::string text;
  bool end = false;
};

} // namespace

struct HttpFront::Impl {
  int listen_fd;
  std::size_t max_body;
  Serve serve;
  int epoll_fd = -1, wake_fd = -1;
  std::atomic<bool> running{false};
  std::thread io, pump;
  std::vector<std::thread> workers;
  std::map<uint64_t, Conn> conns; // the I/O thread's alone
  uint64_t next_id = 1;
  std::atomic<std::size_t> conn_count{0};

  std::mutex jobs_mutex;
  std::condition_variable jobs_cv;
  std::deque<Job> jobs;

  std::mutex done_mutex;
  std::deque<Done> done;
  std::deque<StreamText> stream_text;

  std::mutex streams_mutex;
  std::condition_variable pump_cv;
  std::map<uint64_t, std::shared_ptr<EventStream>> streams;

  Impl(int fd, std::size_t body, Serve s) : listen_fd(fd), max_body(body), serve(std::move(s)) {
    fcntl(listen_fd, F_SETFL, fcntl(listen_fd, F_GETFL) | O_NONBLOCK);
    epoll_fd = epoll_create1(EPOLL_CLOEXEC);
    wake_fd = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
    if (epoll_fd < 0 || wake_fd < 0) throw std::runtime_error(fmt::format("http: {}", std::strerror(errno)));
    epoll_event ev{};
    ev.events = EPOLLIN;
    ev.data.u64 = 0; // the listening socket
    epoll_ctl(epoll_fd, EPOLL_CTL_ADD, listen_fd, &ev);
    ev.data.u64 = UINT64_MAX; // the wake-up
    epoll_ctl(epoll_fd, EPOLL_CTL_ADD, wake_fd, &ev);
  }

  ~Impl() {
    stop();
    if (wake_fd >= 0) close(wake_fd);
    if (epoll_fd >= 0) close(epoll_fd);
  }

  void wake() {
    const uint64_t one = 1;
    [[maybe_unused]] const ssize_t n = ::write(wake_fd, &one, sizeof one);
  }

  // ---- the I/O thread ----
  void arm(Conn& c) {
    uint32_t want = 0;
    switch (c.phase) {
      case Phase::Reading: want = EPOLLIN | EPOLLRDHUP; break;
      case Phase::Working: want = 0; break; // not watched: nothing is read while a worker has the request
      case Phase::Writing: want = EPOLLOUT; break;
      case Phase::Streaming: want = EPOLLRDHUP | EPOLLIN | (c.out_at < c.out.size() ? EPOLLOUT : 0u); break;
    }
    if (want == c.armed) return;
    epoll_event ev{};
    ev.events = want;
    ev.data.u64 = c.id;
    if (want == 0) epoll_ctl(epoll_fd, EPOLL_CTL_DEL, c.fd, &ev);
    else epoll_ctl(epoll_fd, c.armed == 0 ? EPOLL_CTL_ADD : EPOLL_CTL_MOD, c.fd, &ev);
    c.armed = want;
  }

  void close_conn(uint64_t id) {
    const auto it = conns.find(id);
    if (it == conns.end()) return;
    if (it->second.armed != 0) epoll_ctl(epoll_fd, EPOLL_CTL_DEL, it->second.fd, nullptr);
    ::close(it->second.fd);
    if (it->second.stream) {
      std::lock_guard lock(streams_mutex);
      streams.erase(id);
    }
    conns.erase(it);
    conn_count.store(conns.size());
  }

  // The connection waiting for its request the longest (idle or trickling).
  bool evict_one() {
    auto victim = conns.end();
    const auto since = [](const Conn& c) { return c.in.empty() ? c.last_byte : c.request_start; };
    for (auto it = conns.begin(); it != conns.end(); ++it)
      if (it->second.phase == Phase::Reading && (victim == conns.end() || since(it->second) < since(victim->second)))
        victim = it;
    if (victim == conns.end()) return false;
    close_conn(victim->first);
    return true;
  }

  void accept_all() {
    for (;;) {
      const int fd = accept4(listen_fd, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
      if (fd < 0) return;
      if (conns.size() >= kMaxConnections && !evict_one()) {
        ::close(fd);
        continue;
      }
      const int yes = 1;
      setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
      Conn& c = conns[next_id];
      c.id = next_id++;
      c.fd = fd;
      c.last_byte = Clock::now();
      arm(c);
      conn_count.store(conns.size());
    }
  }

  // Answers the front gives itself: sent, then the connection closes.
  void refuse(Conn& c, std::string bytes) {
    c.in.clear();
    c.out = std::move(bytes);
    c.out_at = 0;
    c.keep_alive = false;
    c.phase = Phase::Writing;
    c.write_start = Clock::now();
  }

  // A whole request in the buffer goes to a worker; a refused one is answered here.
  void try_dispatch(Conn& c) {
    if (c.phase != Phase::Reading || c.in.empty()) return;
    const auto end = c.in.find("\r\n\r\n");
    if (end == std::string::npos) {
      if (c.in.size() > kMaxHeaderBytes) refuse(c, refusal(431, "Request Header Fields Too Large", "request headers too large"));
      return;
    }
    if (end + 4 > kMaxHeaderBytes) return refuse(c, refusal(431, "Request Header Fields Too Large", "request headers too large"));
    std::size_t length = 0;
    bool expect_continue = false;
    std::size_t expect_at = std::string::npos, expect_len = 0;
    for (std::size_t at = c.in.find("\r\n") + 2; at < end + 2;) {
      const std::size_t eol = c.in.find("\r\n", at);
      const std::string_view line(c.in.data() + at, eol - at);
      if (iequals_prefix(line, "transfer-encoding:"))
        return refuse(c, refusal(411, "Length Required", "a request body needs Content-Length (no chunked bodies)"));
      if (iequals_prefix(line, "content-length:")) {
        const std::string v = trim(line.substr(15));
        if (v.empty() || v.size() > 12 || v.find_first_not_of("0123456789") != std::string::npos)
          return refuse(c, refusal(400, "Bad Request", "bad Content-Length"));
        length = std::stoull(v);
        if (length > max_body) return refuse(c, refusal(413, "Payload Too Large", "request body too large"));
      }
      if (iequals_prefix(line, "expect:")) {
        expect_continue = true;
        expect_at = at;
        expect_len = eol + 2 - at;
      }
      at = eol + 2;
    }
    if (c.in.size() < end + 4 + length) {
      if (expect_continue && !c.sent_continue) { // the client waits for this before its body
        static constexpr char kContinue[] = "HTTP/1.1 100 Continue\r\n\r\n";
        [[maybe_unused]] const ssize_t n = send(c.fd, kContinue, sizeof kContinue - 1, MSG_NOSIGNAL);
        c.sent_continue = true;
      }
      return;
    }
    std::string request = c.in.substr(0, end + 4 + length);
    c.in.erase(0, end + 4 + length);
    if (expect_at != std::string::npos) request.erase(expect_at, expect_len); // answered here already
    c.sent_continue = false;
    c.phase = Phase::Working;
    {
      std::lock_guard lock(jobs_mutex);
      jobs.push_back(Job{c.id, c.fd, std::move(request)});
    }
    jobs_cv.notify_one();
  }

  void read_some(Conn& c) {
    char buf[8192];
    for (;;) {
      const ssize_t n = recv(c.fd, buf, sizeof buf, 0);
      if (n > 0) {
        const auto now = Clock::now();
        if (c.in.empty()) c.request_start = now;
        c.last_byte = now;
        if (c.phase == Phase::Streaming) continue; // a stream's client has nothing to say
        c.in.append(buf, static_cast<std::size_t>(n));
        if (c.in.size() > kMaxHeaderBytes + max_body + 4) break; // refused by try_dispatch
        continue;
      }
      if (n < 0 && errno == EINTR) continue;
      if (n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK)) c.peer_closed = true;
      return;
    }
  }

  // Sends what the socket takes now; c.out is empty once all is sent.
  void write_some(Conn& c) {
    while (c.out_at < c.out.size()) {
      const ssize_t n = send(c.fd, c.out.data() + c.out_at, c.out.size() - c.out_at, MSG_NOSIGNAL);
      if (n > 0) {
        c.out_at += static_cast<std::size_t>(n);
        continue;
      }
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return;
      c.write_failed = true;
      return;
    }
    c.out.clear();
    c.out_at = 0;
  }

  // After any event on c: move it along its phases; false: close it.
  bool advance(Conn& c) {
    if (c.phase == Phase::Writing) {
      write_some(c);
      if (c.write_failed) return false;
      if (!c.out.empty()) return true;
      if (c.peer_closed && !c.stream) return false; // answered; the client has gone
      if (c.stream) {
        c.phase = Phase::Streaming;
        std::lock_guard lock(streams_mutex);
        streams[c.id] = c.stream;
      } else if (!c.keep_alive) {
        return false;
      } else {
        c.phase = Phase::Reading;
        c.last_byte = Clock::now();
        if (!c.in.empty()) c.request_start = c.last_byte; // a pipelined request: its own deadline
      }
    }
    if (c.phase == Phase::Streaming) {
      write_some(c);
      return !c.peer_closed && !c.write_failed;
    }
    if (c.phase == Phase::Reading) {
      try_dispatch(c);
      if (c.phase == Phase::Writing) return advance(c);
      if (c.peer_closed && c.phase == Phase::Reading) return false; // the client went before its request was whole
    }
    return true;
  }

  void on_event(uint64_t id, uint32_t events) {
    const auto it = conns.find(id);
    if (it == conns.end()) return;
    Conn& c = it->second;
    if (events & (EPOLLIN | EPOLLRDHUP | EPOLLHUP | EPOLLERR)) {
      if (c.phase == Phase::Reading || c.phase == Phase::Streaming) read_some(c);
      if (events & (EPOLLHUP | EPOLLERR)) c.peer_closed = true;
    }
    if (!advance(c)) return close_conn(id);
    arm(c);
  }

  void take_done() {
    std::deque<Done> d;
    std::deque<StreamText> t;
    {
      std::lock_guard lock(done_mutex);
      d.swap(done);
      t.swap(stream_text);
    }
    for (auto& x : d) {
      const auto it = conns.find(x.id);
      if (it == conns.end()) continue;
      Conn& c = it->second;
      c.out = std::move(x.answer.bytes);
      c.out_at = 0;
      c.keep_alive = x.answer.keep_alive;
      c.stream = std::move(x.answer.stream);
      c.phase = Phase::Writing;
      c.write_start = Clock::now();
      if (!advance(c)) close_conn(x.id);
      else arm(c);
    }
    for (auto& x : t) {
      const auto it = conns.find(x.id);
      if (it == conns.end() || it->second.phase != Phase::Streaming) continue;
      Conn& c = it->second;
      if (x.end) {
        close_conn(x.id);
        continue;
      }
      c.out += x.text;
      if (c.out.size() - c.out_at > kMaxStreamBacklog) { // the client does not keep up: it reconnects and resumes
        close_conn(x.id);
        continue;
      }
      if (!advance(c)) close_conn(x.id);
      else arm(c);
    }
  }

  void sweep() {
    const auto now = Clock::now();
    std::vector<uint64_t> expired;
    for (auto& [id, c] : conns) {
      const bool idle = c.phase == Phase::Reading && c.in.empty() && now - c.last_byte > kIdleTimeout;
      const bool slow = c.phase == Phase::Reading && !c.in.empty() && now - c.request_start > kRequestDeadline;
      const bool stuck = c.phase == Phase::Writing && now - c.write_start > kWriteDeadline;
      if (idle || slow || stuck) expired.push_back(id);
    }
    for (uint64_t id : expired) close_conn(id);
  }

  void io_loop() {
    std::vector<epoll_event> events(256);
    auto last_sweep = Clock::now();
    while (running.load()) {
      const int n = epoll_wait(epoll_fd, events.data(), static_cast<int>(events.size()), 50);
      for (int i = 0; i < n; ++i) {
        const uint64_t id = events[static_cast<std::size_t>(i)].data.u64;
        if (id == 0) {
          accept_all();
        } else if (id == UINT64_MAX) {
          uint64_t v = 0;
          [[maybe_unused]] const ssize_t r = ::read(wake_fd, &v, sizeof v);
        } else {
          on_event(id, events[static_cast<std::size_t>(i)].events);
        }
      }
      take_done();
      if (Clock::now() - last_sweep > std::chrono::milliseconds(50)) {
        sweep();
        last_sweep = Clock::now();
      }
    }
  }

  // ---- workers and the stream pump ----
  void work() {
    for (;;) {
      Job job;
      {
        std::unique_lock lock(jobs_mutex);
        jobs_cv.wait(lock, [this] { return !running.load() || !jobs.empty(); });
        if (!running.load()) return;
        job = std::move(jobs.front());
        jobs.pop_front();
      }
      FrontAnswer a;
      try {
        a = serve(job.request, job.fd);
      } catch (const std::exception& e) {
        a.bytes = refusal(500, "Internal Server Error", "internal error");
        a.keep_alive = false;
      }
      {
        std::lock_guard lock(done_mutex);
        done.push_back(Done{job.id, std::move(a)});
      }
      wake();
    }
  }

  void pump_loop() {
    std::unique_lock lock(streams_mutex);
    while (running.load()) {
      pump_cv.wait_for(lock, kStreamPoll, [this] { return !running.load(); });
      if (!running.load()) return;
      const auto all = streams; // the streams' own locks are taken without ours
      lock.unlock();
      std::deque<StreamText> out;
      for (const auto& [id, s] : all) {
        if (!s->alive()) out.push_back(StreamText{id, "", true});
        else if (std::string text = s->next(); !text.empty()) out.push_back(StreamText{id, std::move(text)});
      }
      if (!out.empty()) {
        {
          std::lock_guard d(done_mutex);
          for (auto& x : out) stream_text.push_back(std::move(x));
        }
        wake();
      }
      lock.lock();
    }
  }

  void start() {
    if (running.exchange(true)) return;
    io = std::thread([this] { io_loop(); });
    pump = std::thread([this] { pump_loop(); });
    for (int i = 0; i < kWorkers; ++i) workers.emplace_back([this] { work(); });
  }

  void stop() {
    if (!running.exchange(false)) return;
    wake();
    jobs_cv.notify_all();
    {
      std::lock_guard lock(streams_mutex);
      pump_cv.notify_all();
    }
    if (io.joinable()) io.join();
    if (pump.joinable()) pump.join();
    for (auto& w : workers) w.join();
    workers.clear();
    std::vector<uint64_t> ids;
    for (const auto& [id, c] : conns) ids.push_back(id);
    for (uint64_t id : ids) close_conn(id);
  }
};

HttpFront::HttpFront(int listen_fd, std::size_t max_body_bytes, Serve serve)
    : impl_(std::make_unique<Impl>(listen_fd, max_body_bytes, std::move(serve))) {}
HttpFront::~HttpFront() = default;
void HttpFront::start() { impl_->start(); }
void HttpFront::stop() { impl_->stop(); }
std::size_t HttpFront::connections() const { return impl_->conn_count.load(); }

} // namespace sreh::serve
