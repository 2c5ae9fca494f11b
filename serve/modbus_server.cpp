#include "serve/modbus_server.hpp"

#include <arpa/inet.h>
#include <modbus/modbus.h>
#include <netinet/in.h>
#include <sys/select.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "serve/front_impl.hpp"
#include "serve/modbus_map.hpp"

namespace sreh::serve {
namespace {
constexpr int kMaxClients = 32;
constexpr int kHeader = 7; // MBAP header: transaction, protocol, length, unit id

int fd_port(int fd) {
  sockaddr_storage addr{};
  socklen_t len = sizeof addr;
  if (getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len) != 0) return -1;
  if (addr.ss_family == AF_INET) return ntohs(reinterpret_cast<sockaddr_in*>(&addr)->sin_port);
  if (addr.ss_family == AF_INET6) return ntohs(reinterpret_cast<sockaddr_in6*>(&addr)->sin6_port);
  return -1;
}
} // namespace

template <>
struct Front<ModbusOptions>::Impl {
  Hub& hub;
  ModbusOptions options;
  modbus_t* ctx = nullptr;
  modbus_mapping_t* mapping = nullptr;
  int listen_fd = -1;
  std::vector<int> clients;
  std::vector<modbus::PortRegisters> regs;
  std::atomic<bool> running{false};
  std::thread thread;

  Impl(Hub& h, const ModbusOptions& o) : hub(h), options(o), regs(static_cast<std::size_t>(h.port_count())) {
    const std::string service = std::to_string(o.port);
    ctx = modbus_new_tcp_pi(o.host.c_str(), service.c_str());
    if (ctx == nullptr) throw std::runtime_error(fmt::format("modbus: cannot use {}:{}", o.host, o.port));
    // A client that stops in the middle of a frame costs at most 200 ms.
    modbus_set_byte_timeout(ctx, 0, 200000);
    modbus_set_indication_timeout(ctx, 0, 200000);
    listen_fd = modbus_tcp_pi_listen(ctx, 16);
    if (listen_fd < 0) {
      const std::string why = modbus_strerror(errno);
      modbus_free(ctx);
      throw std::runtime_error(fmt::format("modbus: cannot listen on {}:{}: {}", o.host, o.port, why));
    }
    mapping = modbus_mapping_new_start_address(0, 0, 0, 0, 0,
                                               static_cast<unsigned>(modbus::register_count(h.port_count())), 0, 0);
    if (mapping == nullptr) throw std::runtime_error("modbus: out of memory for the register map");
  }

  ~Impl() {
    for (int fd : clients) close(fd);
    if (listen_fd >= 0) close(listen_fd);
    if (mapping != nullptr) modbus_mapping_free(mapping);
    if (ctx != nullptr) modbus_free(ctx);
  }

  void exception(const uint8_t* query, unsigned code) { modbus_reply_exception(ctx, query, code); }

  // Reads: refresh every port block the range touches, then reply.
  void handle_read(const uint8_t* q, int len) {
    const int addr = (q[kHeader + 1] << 8) | q[kHeader + 2];
    const int count = (q[kHeader + 3] << 8) | q[kHeader + 4];
    if (count < 1 || count > MODBUS_MAX_READ_REGISTERS) return exception(q, MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE);
    if (addr + count > modbus::register_count(hub.port_count()))
      return exception(q, MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS);
    uint16_t* r = mapping->tab_registers;
    if (addr < modbus::kPortBlock) modbus::fill_global(r, hub.port_count(), hub.options().cycle_s);
    for (int p = std::max(1, addr / modbus::kPortBlock); p <= (addr + count - 1) / modbus::kPortBlock; ++p) {
      hub.with_port(p, [&](Hub::Port& port) {
        modbus::fill_port(r + modbus::port_base(p), port, regs[static_cast<std::size_t>(p - 1)]);
      });
    }
    modbus_reply(ctx, q, len, mapping);
  }

  void handle_write(const uint8_t* q, int len, bool multiple) {
    if (!options.writes_allowed) return exception(q, MODBUS_EXCEPTION_ILLEGAL_FUNCTION);
    const int addr = (q[kHeader + 1] << 8) | q[kHeader + 2];
    std::vector<uint16_t> values;
    if (multiple) {
      const int count = (q[kHeader + 3] << 8) | q[kHeader + 4];
      const int bytes = q[kHeader + 5];
      if (count < 1 || count > MODBUS_MAX_WRITE_REGISTERS || bytes != 2 * count || len < kHeader + 6 + bytes)
        return exception(q, MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE);
      for (int i = 0; i < count; ++i)
        values.push_back(static_cast<uint16_t>((q[kHeader + 6 + 2 * i] << 8) | q[kHeader + 7 + 2 * i]));
    } else {
      values.push_back(static_cast<uint16_t>((q[kHeader + 3] << 8) | q[kHeader + 4]));
    }
    const int count = static_cast<int>(values.size());
    const int p = addr / modbus::kPortBlock, offset = addr % modbus::kPortBlock;
    if (!hub.valid_port(p) || !modbus::writable(offset, count))
      return exception(q, MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS);
    uint16_t* block = mapping->tab_registers + modbus::port_base(p);
    std::string refused;
    hub.with_port(p, [&](Hub::Port& port) {
      auto& port_regs = regs[static_cast<std::size_t>(p - 1)];
      modbus::fill_port(block, port, port_regs);
      refused = modbus::check_write(offset, values, block);
      if (!refused.empty()) return;
      std::copy(values.begin(), values.end(), block + offset);
      modbus::apply_write(block, offset, count, port, port_regs);
    });
    if (!refused.empty()) return exception(q, MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE);
    modbus_reply(ctx, q, len, mapping); // echoes the request (values already in place)
  }

  // false: drop the client (malformed frame or closed connection).
  bool serve_client(int fd) {
    modbus_set_socket(ctx, fd);
    uint8_t q[MODBUS_TCP_MAX_ADU_LENGTH];
    const int len = modbus_receive(ctx, q);
    if (len <= 0) return false;
    switch (q[kHeader]) {
      case MODBUS_FC_READ_HOLDING_REGISTERS: handle_read(q, len); break;
      case MODBUS_FC_WRITE_SINGLE_REGISTER: handle_write(q, len, false); break;
      case MODBUS_FC_WRITE_MULTIPLE_REGISTERS: handle_write(q, len, true); break;
      default: exception(q, MODBUS_EXCEPTION_ILLEGAL_FUNCTION); break;
    }
    return true;
  }

  void loop() {
    while (running.load()) {
      fd_set set;
      FD_ZERO(&set);
      FD_SET(listen_fd, &set);
      int max_fd = listen_fd;
      for (int fd : clients) {
        FD_SET(fd, &set);
        max_fd = std::max(max_fd, fd);
      }
      timeval tv{0, 100000}; // wake up to notice stop()
      const int n = select(max_fd + 1, &set, nullptr, nullptr, &tv);
      if (n < 0) {
        if (errno == EINTR) continue;
        break;
      }
      if (n == 0) continue;
      if (FD_ISSET(listen_fd, &set)) {
        const int fd = accept(listen_fd, nullptr, nullptr);
        if (fd >= 0) {
          if (static_cast<int>(clients.size()) >= kMaxClients || fd >= FD_SETSIZE) close(fd);
          else clients.push_back(fd);
        }
      }
      for (std::size_t i = 0; i < clients.size();) {
        const int fd = clients[i];
        if (FD_ISSET(fd, &set) && !serve_client(fd)) {
          close(fd);
          clients.erase(clients.begin() + static_cast<std::ptrdiff_t>(i));
        } else {
          ++i;
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
