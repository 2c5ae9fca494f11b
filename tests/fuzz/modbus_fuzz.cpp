// libFuzzer target (issue 27): the Modbus TCP server's framing and request
// handling, as one client connection's byte stream. Frames are taken the
// way serve/modbus_server.cpp takes them (next_frame, pdu_length_matches,
// handle); a Bad frame or a length mismatch ends the connection there.
// Every answer: MBAP length right, at most 260 octets, an exception's
// function byte = the request's | 0x80 with code 1..3.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <span>
#include <vector>

#include "serve/hub.hpp"
#include "serve/modbus_frame.hpp"
#include "serve/modbus_handler.hpp"

namespace {
sreh::serve::Hub& hub() {
  static auto* h = new sreh::serve::Hub(std::vector<sreh::TwinConfig>(2), sreh::serve::HubOptions{}); // MuJoCo once
  return *h;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace sreh::serve::modbus;
  Session session(hub().port_count());
  session.may_write = size % 2 == 0; // both kinds of client
  EventTrackers events(static_cast<std::size_t>(hub().port_count()));
  std::span<const uint8_t> in(data, size);
  for (int frames = 0; frames < 64; ++frames) {
    const Frame f = next_frame(in);
    if (f.status != Frame::Status::Ready) break; // NeedMore: the deadline closes it; Bad: closed
    if (f.size < kMbapBytes + 1 || f.size > in.size()) std::abort();
    const Request r = split(in.first(f.size));
    in = in.subspan(f.size);
    if (!pdu_length_matches(r.pdu)) break;
    const Outcome o = handle(hub(), session, events, r.pdu);
    const std::vector<uint8_t> adu = answer(r, o.pdu);
    if (o.pdu.empty() || adu.size() > 260 || be16(&adu[4]) != adu.size() - 6) std::abort();
    if ((o.pdu[0] & 0x80) != 0 && (o.pdu.size() != 2 || o.pdu[0] != (r.pdu[0] | 0x80) || o.pdu[1] < 1 || o.pdu[1] > 3))
      std::abort();
    if ((o.pdu[0] & 0x80) == 0 && o.pdu[0] != r.pdu[0]) std::abort();
  }
  return 0;
}
