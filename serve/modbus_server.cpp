#include "serve/modbus_server.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <list>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "serve/front_impl.hpp"
#include "serve/listen_socket.hpp"
#include "serve/modbus_frame.hpp"
#include "serve/modbus_handler.hpp"

namespace sreh::serve {
namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kFrameDeadline = std::chrono::milliseconds(1000); // a started frame must be in by then
constexpr int kFramesPerTurn = 8;         // then the next client gets its turn
constexpr std::size_t kMaxPendingOut = 64 * 1024; // a client that does not read its answers is dropped
constexpr int kPollMs = 20;
// Eviction by progress (issue 40): a connection that completed a request
// within this window is working and is never evicted; among the others
// (silent, or never finishing a frame however often it restarts one) the
// one whose last completed request (or connect) lies furthest back goes.
constexpr auto kWorkingWindow = std::chrono::seconds(5);

std::string peer_address(int fd) {
  sockaddr_storage addr{};
  socklen_t len = sizeof addr;
  if (getpeername(fd, reinterpret_cast<sockaddr*>(&addr), &len) != 0) return "";
  char text[INET6_ADDRSTRLEN] = {};
  if (addr.ss_family == AF_INET)
    inet_ntop(AF_INET, &reinterpret_cast<sockaddr_in*>(&addr)->sin_addr, text, sizeof text);
  else if (addr.ss_family == AF_INET6)
    inet_ntop(AF_INET6, &reinterpret_cast<sockaddr_in6*>(&addr)->sin6_addr, text, sizeof text);
  return text;
}

struct Client {
  Client(int fd_, int ports) : fd(fd_), session(ports), last_activity(Clock::now()), progress(last_activity) {}
  int fd;
  modbus::Session session;
  std::vector<uint8_t> in, out;
  Clock::time_point last_activity;
  Clock::time_point frame_start; // when the first octet of the unfinished frame came
  Clock::time_point progress;    // the last completed request (connect until the first)
  bool completed_any = false;
  bool eof = false;      // the client closed its side: answer what is in, then close
  bool closing = false;  // close now, without answering more
};

// A complete request is in: what the client already sent (read or still in
// the socket) holds the MBAP header and as many octets as its length field
// counts (Modbus Messaging on TCP/IP 3.1.3). Such a client is working even
// if the loop has not served it yet: under load a new client's first
// request can wait in its socket while reconnecting clients queue behind it.
bool request_waiting(const Client& c) {
  std::vector<uint8_t> sent = c.in;
  uint8_t peek[260];
  const ssize_t n = recv(c.fd, peek, sizeof peek, MSG_PEEK | MSG_DONTWAIT);
  if (n > 0) sent.insert(sent.end(), peek, peek + n);
  if (sent.size() < 6) return false;
  const std::size_t length = (std::size_t{sent[4]} << 8) | sent[5];
  return sent.size() >= 6 + length;
}

} // namespace

template <>
struct Front<ModbusOptions>::Impl {
  Hub& hub;
  ModbusOptions options;
  int listen_fd = -1;
  std::list<Client> clients;
  modbus::EventTrackers events;
  std::atomic<bool> running{false};
  std::thread thread;

  Impl(Hub& h, const ModbusOptions& o) : hub(h), options(o), events(static_cast<std::size_t>(h.port_count())) {
    listen_fd = listen_tcp(o.host, o.port, "modbus", 64);
  }

  ~Impl() {
    stop();
    for (auto& c : clients) close(c.fd);
    if (listen_fd >= 0) close(listen_fd);
  }

  void accept_clients() {
    for (;;) {
      const int fd = accept4(listen_fd, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
      if (fd < 0) return; // EAGAIN: no more for now
      const int yes = 1;
      setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
      if (static_cast<int>(clients.size()) >= options.max_clients && !evict_one()) {
        close(fd); // every connection is working: the newest waits its turn
        continue;
      }
      Client& c = clients.emplace_back(fd, hub.port_count());
      c.session.may_write = !options.token_set ||
                            std::find(options.writers.begin(), options.writers.end(), peer_address(fd)) != options.writers.end();
    }
  }

  // The limit is reached: the connection that has not completed a request
  // for the longest makes room, unless every one is working (kWorkingWindow)
  // or has a complete request waiting to be served.
  bool evict_one() {
    const auto now = Clock::now();
    auto victim = clients.end();
    for (auto it = clients.begin(); it != clients.end(); ++it) {
      if (it->completed_any && now - it->progress < kWorkingWindow) continue;
      if (request_waiting(*it)) continue;
      if (victim == clients.end() || it->progress < victim->progress) victim = it;
    }
    if (victim == clients.end()) return false;
    close(victim->fd);
    clients.erase(victim);
    return true;
  }

  void receive(Client& c) {
    uint8_t buf[4096];
    for (;;) {
      const ssize_t n = recv(c.fd, buf, sizeof buf, 0);
      if (n > 0) {
        if (c.in.empty()) c.frame_start = Clock::now();
        c.in.insert(c.in.end(), buf, buf + n);
        c.last_activity = Clock::now();
        if (c.in.size() > 16 * 1024) break; // served before more is read
        continue;
      }
      if (n < 0 && errno == EINTR) continue;
      if (n == 0) c.eof = true;
      else if (errno != EAGAIN && errno != EWOULDBLOCK) c.closing = true;
      return;
    }
  }

  void serve_frames(Client& c) {
    for (int k = 0; k < kFramesPerTurn && !c.closing && c.out.size() < kMaxPendingOut; ++k) {
      const modbus::Frame f = modbus::next_frame(c.in);
      if (f.status == modbus::Frame::Status::Bad) {
        c.closing = true; // not Modbus TCP: no answer
        return;
      }
      if (f.status == modbus::Frame::Status::NeedMore) return;
      const modbus::Request r = modbus::split(std::span<const uint8_t>(c.in.data(), f.size));
      if (!modbus::pdu_length_matches(r.pdu)) {
        c.closing = true;
        return;
      }
      const modbus::Outcome o = modbus::handle(hub, c.session, events, r.pdu);
      c.progress = Clock::now();
      c.completed_any = true;
      const auto adu = modbus::answer(r, o.pdu);
      c.out.insert(c.out.end(), adu.begin(), adu.end());
      c.in.erase(c.in.begin(), c.in.begin() + static_cast<std::ptrdiff_t>(f.size));
      if (!c.in.empty()) c.frame_start = Clock::now();
    }
  }

  void send_pending(Client& c) {
    while (!c.out.empty()) {
      const ssize_t n = send(c.fd, c.out.data(), c.out.size(), MSG_NOSIGNAL);
      if (n > 0) {
        c.out.erase(c.out.begin(), c.out.begin() + n);
        continue;
      }
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return;
      c.closing = true;
      return;
    }
  }

  void loop() {
    const auto idle = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.idle_timeout_s));
    std::vector<pollfd> fds;
    bool backlog = false; // a client has whole frames waiting beyond its turn: do not sleep in poll()
    while (running.load()) {
      fds.clear();
      fds.push_back({listen_fd, POLLIN, 0});
      for (auto& c : clients) {
        short want = 0;
        if (c.out.size() < kMaxPendingOut && !c.eof) want |= POLLIN;
        if (!c.out.empty()) want |= POLLOUT;
        fds.push_back({c.fd, want, 0});
      }
      const int n = poll(fds.data(), fds.size(), backlog ? 0 : kPollMs);
      backlog = false;
      if (n < 0 && errno != EINTR) break;
      if (n > 0 && (fds[0].revents & POLLIN)) accept_clients();
      std::size_t i = 1;
      const auto now = Clock::now();
      for (auto it = clients.begin(); it != clients.end();) {
        Client& c = *it;
        const short ev = i < fds.size() && fds[i].fd == c.fd ? fds[i].revents : 0;
        ++i;
        if ((ev & (POLLIN | POLLHUP | POLLERR)) && !c.eof) receive(c);
        serve_frames(c);
        send_pending(c);
        if (!c.in.empty() && now - c.frame_start > kFrameDeadline) c.closing = true;    // a frame that never ends
        if (c.in.empty() && c.out.empty() && now - c.last_activity > idle) c.closing = true; // idle timeout
        if (c.eof && c.out.empty() && modbus::next_frame(c.in).status != modbus::Frame::Status::Ready) c.closing = true;
        if (c.closing) {
          close(c.fd);
          it = clients.erase(it);
        } else {
          backlog = backlog || (c.out.size() < kMaxPendingOut && modbus::next_frame(c.in).status == modbus::Frame::Status::Ready);
          ++it;
        }
      }
    }
  }

  int port() const { return fd_port(listen_fd); }
  void start() {
    if (running.exchange(true)) return;
    thread = std::thread([this] { loop(); });
  }
  void stop() {
    running.store(false);
    if (thread.joinable()) thread.join();
  }
};

template class Front<ModbusOptions>;

} // namespace sreh::serve
