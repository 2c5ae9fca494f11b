#include "serve/modbus_handler.hpp"

#include <algorithm>

#include "serve/modbus_frame.hpp"

namespace sreh::serve::modbus {
namespace {

constexpr int kMaxRead = 125;       // Modbus: registers per read
constexpr int kMaxWrite = 123;      // FC 16
constexpr int kMaxReadWrite = 121;  // FC 23's write part

struct Refusal {
  uint8_t code;
};

std::vector<uint8_t> exception_pdu(uint8_t function, uint8_t code) { return {static_cast<uint8_t>(function | 0x80), code}; }

void check_read(Hub& hub, int addr, int count) {
  if (count < 1 || count > kMaxRead) throw Refusal{kIllegalValue};
  if (addr + count > register_count(hub.port_count())) throw Refusal{kIllegalAddress};
}

// Reads [addr, addr + count): refresh every block the range touches.
std::vector<uint16_t> read_range(Hub& hub, Session& s, EventTrackers& events, int addr, int count) {
  check_read(hub, addr, count);
  std::vector<uint16_t> out(static_cast<std::size_t>(count), 0);
  std::vector<uint16_t> block(kPortBlock, 0);
  for (int b = addr / kPortBlock; b <= (addr + count - 1) / kPortBlock; ++b) {
    std::fill(block.begin(), block.end(), 0);
    if (b == 0) {
      fill_global(block.data(), hub.port_count(), hub.options().cycle_s);
    } else {
      const auto i = static_cast<std::size_t>(b - 1);
      const PortRegisters& window = s.own[i] ? s.windows[i] : events[i].last_isdu;
      hub.with_port(b, [&](Hub::Port& port) { fill_port(block.data(), port, window, events[i].events); });
    }
    const int from = std::max(addr, b * kPortBlock), to = std::min(addr + count, (b + 1) * kPortBlock);
    for (int r = from; r < to; ++r) out[static_cast<std::size_t>(r - addr)] = block[static_cast<std::size_t>(r - b * kPortBlock)];
  }
  return out;
}

// Writes values at addr (one port block); an ISDU write is durable or refused.
void write_range(Hub& hub, Session& s, EventTrackers& events, int addr, const std::vector<uint16_t>& values) {
  const int count = static_cast<int>(values.size());
  const int p = addr / kPortBlock, offset = addr % kPortBlock;
  if (!hub.valid_port(p) || !writable(offset, count)) throw Refusal{kIllegalAddress};
  if (!s.may_write && !read_only_request(offset, values)) throw Refusal{kIllegalFunction};
  const auto i = static_cast<std::size_t>(p - 1);
  const bool isdu = offset + count > kIsduCommand;
  if (isdu && !s.own[i]) { // from now on this connection's own window, starting as the port's
    s.windows[i] = events[i].last_isdu;
    s.own[i] = true;
  }
  PortRegisters& window = s.own[i] ? s.windows[i] : events[i].last_isdu;
  std::vector<uint16_t> block(kPortBlock, 0);
  bool refused = false;
  hub.with_port(p, [&](Hub::Port& port) {
    fill_port(block.data(), port, window, events[i].events);
    if (!check_write(offset, values, block.data()).empty()) {
      refused = true;
      return;
    }
    std::copy(values.begin(), values.end(), block.begin() + offset);
    const auto before = hub.checkpoint(port); // an ISDU write is saved before it is answered, or undone
    if (apply_write(block.data(), offset, count, port, window))
      if (const uint16_t code = hub.commit(p, port, before)) refuse_isdu(window, code);
  });
  if (refused) throw Refusal{kIllegalValue};
  if (isdu) events[i].last_isdu = window; // what a connection without its own window reads
}

std::vector<uint16_t> registers_at(std::span<const uint8_t> bytes, int count) {
  std::vector<uint16_t> v;
  for (int k = 0; k < count; ++k) v.push_back(be16(&bytes[static_cast<std::size_t>(2 * k)]));
  return v;
}

void put_registers(std::vector<uint8_t>& pdu, const std::vector<uint16_t>& regs) {
  pdu.push_back(static_cast<uint8_t>(2 * regs.size()));
  for (uint16_t r : regs) {
    pdu.push_back(static_cast<uint8_t>(r >> 8));
    pdu.push_back(static_cast<uint8_t>(r & 0xFF));
  }
}

} // namespace

Outcome handle(Hub& hub, Session& s, EventTrackers& events, std::span<const uint8_t> pdu) {
  Outcome o;
  const uint8_t fc = pdu[0];
  try {
    switch (fc) {
      case kReadHolding: {
        const auto regs = read_range(hub, s, events, be16(&pdu[1]), be16(&pdu[3]));
        o.pdu = {fc};
        put_registers(o.pdu, regs);
        break;
      }
      case kWriteSingle: {
        write_range(hub, s, events, be16(&pdu[1]), {be16(&pdu[3])});
        o.pdu.assign(pdu.begin(), pdu.end()); // echo
        break;
      }
      case kWriteMultiple: {
        const int count = be16(&pdu[3]);
        if (count < 1 || count > kMaxWrite || pdu[5] != 2 * count) throw Refusal{kIllegalValue};
        write_range(hub, s, events, be16(&pdu[1]), registers_at(pdu.subspan(6), count));
        o.pdu.assign(pdu.begin(), pdu.begin() + 5);
        break;
      }
      case kReadWriteMultiple: { // the write is done before the read (Modbus spec 6.17)
        const int read_count = be16(&pdu[3]), write_count = be16(&pdu[7]);
        if (read_count < 1 || read_count > kMaxRead || write_count < 1 || write_count > kMaxReadWrite ||
            pdu[9] != 2 * write_count)
          throw Refusal{kIllegalValue};
        check_read(hub, be16(&pdu[1]), read_count); // both parts checked before either is done (issue 40)
        write_range(hub, s, events, be16(&pdu[5]), registers_at(pdu.subspan(10), write_count));
        const auto regs = read_range(hub, s, events, be16(&pdu[1]), read_count);
        o.pdu = {fc};
        put_registers(o.pdu, regs);
        break;
      }
      default: throw Refusal{kIllegalFunction};
    }
  } catch (const Refusal& r) {
    o.pdu = exception_pdu(fc, r.code);
  }
  return o;
}

} // namespace sreh::serve::modbus
