#include "serve/modbus_map.hpp"

#include <algorithm>

#include "device_logic/parameter_ids.hpp"

namespace sreh::serve::modbus {
namespace {

// Octets into registers, high byte first; an odd last octet pads with 0.
void put_bytes(uint16_t* dst, std::span<const uint8_t> bytes, int count) {
  for (int i = 0; i < count; ++i) {
    const std::size_t hi = 2 * static_cast<std::size_t>(i), lo = hi + 1;
    const uint16_t h = hi < bytes.size() ? bytes[hi] : 0, l = lo < bytes.size() ? bytes[lo] : 0;
    dst[i] = static_cast<uint16_t>((h << 8) | l);
  }
}

std::vector<uint8_t> get_bytes(const uint16_t* src, std::size_t octets) {
  std::vector<uint8_t> out(octets);
  for (std::size_t i = 0; i < octets; ++i)
    out[i] = static_cast<uint8_t>(i % 2 == 0 ? src[i / 2] >> 8 : src[i / 2] & 0xFF);
  return out;
}

bool overlaps(int offset, int count, int start, int n) { return offset < start + n && start < offset + count; }

} // namespace

void fill_global(uint16_t* regs, int ports, double cycle_s) {
  regs[kMapVersion] = 1;
  regs[kPortCount] = static_cast<uint16_t>(ports);
  regs[kCycle100us] = static_cast<uint16_t>(cycle_s * 1e4 + 0.5);
}

void fill_port(uint16_t* block, Hub::Port& port, const PortRegisters& regs, EventTracker& events) {
  Twin& twin = port.twin;
  const bool in_valid = pd_in_valid(port);
  block[kStatus] = static_cast<uint16_t>((in_valid ? 1 : 0) | (port.outputs_valid ? 2 : 0) | (port.failure.empty() ? 0 : 4));
  const PdInFrame in = encode(twin.pd_in());
  put_bytes(block + kPdIn, in, kPdInCount);
  const PdOutFrame out = encode(twin.pd_out());
  put_bytes(block + kPdOut, out, kPdOutCount);
  block[kPdOutValid] = port.outputs_valid ? 1 : 0;
  const Telemetry tel = twin.telemetry();
  block[kState] = static_cast<uint16_t>(tel.state);
  block[kLed] = static_cast<uint16_t>(tel.led);
  std::copy(regs.request.begin(), regs.request.end(), block + kIsduCommand);
  std::copy(regs.response.begin(), regs.response.end(), block + kRespSequence);
  const IsduResult status = twin.isdu_read(param::kDeviceStatus.index, param::kDeviceStatus.subindex);
  block[kDeviceStatus] = status.ok() && !status.data.empty() ? status.data[0] : 0;
  const IsduResult detailed = twin.isdu_read(param::kDetailedDeviceStatus.index, param::kDetailedDeviceStatus.subindex);
  const std::vector<uint8_t> ev = detailed.ok() ? detailed.data : std::vector<uint8_t>{};
  if (ev != events.last_events) {
    ++events.event_changes;
    events.last_events = ev;
  }
  int n = 0;
  std::fill(block + kEvents, block + kEvents + 2 * kEventSlots, 0);
  for (std::size_t i = 0; i + 2 < ev.size() && n < kEventSlots; i += 3) {
    if (ev[i] == 0 && ev[i + 1] == 0 && ev[i + 2] == 0) continue;
    block[kEvents + 2 * n] = ev[i];
    block[kEvents + 2 * n + 1] = static_cast<uint16_t>((ev[i + 1] << 8) | ev[i + 2]);
    ++n;
  }
  block[kEventCount] = static_cast<uint16_t>(n);
  block[kEventChanges] = events.event_changes;
}

bool writable(int offset, int count) {
  const int end = offset + count;
  const bool in_pd = offset >= kPdOut && end <= kPdOutValid + 1;
  const bool in_isdu = offset >= kIsduCommand && end <= kIsduData + kIsduDataCount;
  return count > 0 && (in_pd || in_isdu);
}

bool read_only_request(int offset, const std::vector<uint16_t>& values) {
  const int count = static_cast<int>(values.size());
  if (offset < kIsduCommand || offset + count > kIsduData + kIsduDataCount) return false;
  if (!overlaps(offset, count, kIsduCommand, 1)) return true; // filling in the window runs nothing
  return values[static_cast<std::size_t>(kIsduCommand - offset)] == 1;
}

std::string check_write(int offset, const std::vector<uint16_t>& values, const uint16_t* block) {
  const int count = static_cast<int>(values.size());
  const auto value_at = [&](int reg) { // the register as it will be after the write
    return reg >= offset && reg < offset + count ? values[static_cast<std::size_t>(reg - offset)] : block[reg];
  };
  if (overlaps(offset, count, kPdOutValid, 1) && value_at(kPdOutValid) > 1)
    return "PD out valid register takes 0 or 1";
  // The request registers take only what the map says, also written alone (issue 40).
  if (overlaps(offset, count, kIsduSubindex, 1) && value_at(kIsduSubindex) > 255) return "ISDU subindex is 0 .. 255";
  if (overlaps(offset, count, kIsduLength, 1) && value_at(kIsduLength) > 2 * kIsduDataCount)
    return "ISDU length is 0 .. 232 octets";
  if (overlaps(offset, count, kIsduCommand, 1)) {
    const uint16_t cmd = value_at(kIsduCommand);
    if (cmd != 1 && cmd != 2) return "ISDU command register takes 1 (read) or 2 (write)";
    if (value_at(kIsduSubindex) > 255) return "ISDU subindex is 0 .. 255";
    if (cmd == 2 && value_at(kIsduLength) > 2 * kIsduDataCount) return "ISDU length is 0 .. 232 octets";
  }
  return "";
}

bool apply_write(uint16_t* block, int offset, int count, Hub::Port& port, PortRegisters& regs) {
  if (overlaps(offset, count, kPdOut, kPdOutCount)) {
    const auto bytes = get_bytes(block + kPdOut, kPdOutBytes);
    port.twin.set_pd_out(decode_out(std::span<const uint8_t>(bytes)));
  }
  if (overlaps(offset, count, kPdOutValid, 1)) {
    port.outputs_valid = block[kPdOutValid] == 1;
    port.twin.set_outputs_valid(port.outputs_valid);
  }
  if (overlaps(offset, count, kIsduCommand, kIsduRequestCount)) {
    std::copy(block + kIsduCommand, block + kIsduCommand + kIsduRequestCount, regs.request.begin());
  }
  if (overlaps(offset, count, kIsduCommand, 1)) {
    const uint16_t index = block[kIsduIndex];
    const auto sub = static_cast<uint8_t>(block[kIsduSubindex]);
    IsduResult r;
    if (block[kIsduCommand] == 1) {
      r = port_isdu_read(port, index, sub);
    } else {
      const auto data = get_bytes(block + kIsduData, block[kIsduLength]);
      r = port_isdu_write(port, index, sub, data);
    }
    auto& resp = regs.response;
    resp[0] = static_cast<uint16_t>(resp[0] + 1);
    resp[kRespStatus - kRespSequence] = r.ok() ? 1 : 2;
    resp[kRespError - kRespSequence] = r.error;
    const std::size_t len = std::min<std::size_t>(r.data.size(), 2 * kIsduDataCount);
    resp[kRespLength - kRespSequence] = static_cast<uint16_t>(len);
    put_bytes(resp.data() + (kRespData - kRespSequence), std::span<const uint8_t>(r.data.data(), len), kIsduDataCount);
    std::copy(resp.begin(), resp.end(), block + kRespSequence);
    return block[kIsduCommand] == 2;
  }
  return false;
}

void refuse_isdu(PortRegisters& regs, uint16_t code) {
  auto& resp = regs.response;
  resp[kRespStatus - kRespSequence] = 2;
  resp[kRespError - kRespSequence] = code;
  resp[kRespLength - kRespSequence] = 0;
  std::fill(resp.begin() + (kRespData - kRespSequence), resp.end(), 0);
}

Json map_json(int ports) {
  const auto reg = [](int r, int c, const char* access, const char* what) {
    return Json{{"register", r}, {"count", c}, {"access", access}, {"description", what}};
  };
  Json j;
  j["version"] = 1;
  j["byte_order"] = "big-endian within a register (high byte first), as the manual's process data octets";
  j["addressing"] = "0-based register numbers (PDU addresses)";
  j["read_function_codes"] = {3};
  j["write_function_codes"] = {6, 16, 23};
  j["read_write_function_codes"] = {23};
  j["unit_id"] = "any";
  j["global"] = Json{{"map_version", reg(kMapVersion, 1, "r", "layout version (1)")},
                     {"port_count", reg(kPortCount, 1, "r", "number of ports")},
                     {"master_cycle_100us", reg(kCycle100us, 1, "r", "IO-Link master cycle in 0.1 ms")}};
  j["ports"] = Json::array();
  for (int p = 1; p <= ports; ++p) {
    const int b = port_base(p);
    j["ports"].push_back(Json{
        {"port", p},
        {"base", b},
        {"status", reg(b + kStatus, 1, "r", "bit 0 PD in valid (device communicating), bit 1 PD out valid, bit 2 port failed")},
        {"pd_in", reg(b + kPdIn, kPdInCount, "r", "process data in, 7 octets + 1 pad octet (manual 2.3)")},
        {"pd_out", reg(b + kPdOut, kPdOutCount, "rw", "process data out, 6 octets (manual 2.2)")},
        {"pd_out_valid", reg(b + kPdOutValid, 1, "rw", "1 outputs valid, 0 invalid (manual 5)")},
        {"state", reg(b + kState, 1, "r", "twin extra: 0 MotorOff 1 Ready 2 Busy 3 Done 4 ErrorOn 5 ErrorOff")},
        {"led", reg(b + kLed, 1, "r", "twin extra: 0 off 1 green 2 yellow 3 blue 4 red 5 orange 6 white 7 violet")},
        {"isdu_command", reg(b + kIsduCommand, 1, "rw", "write 1 = read, 2 = write: runs the request")},
        {"isdu_index", reg(b + kIsduIndex, 1, "rw", "index")},
        {"isdu_subindex", reg(b + kIsduSubindex, 1, "rw", "subindex 0 .. 255")},
        {"isdu_length", reg(b + kIsduLength, 1, "rw", "octets to write, 0 .. 232")},
        {"isdu_data", reg(b + kIsduData, kIsduDataCount, "rw", "octets to write")},
        {"isdu_sequence", reg(b + kRespSequence, 1, "r", "+1 for every completed request")},
        {"isdu_status", reg(b + kRespStatus, 1, "r", "0 none yet, 1 ok, 2 refused")},
        {"isdu_error", reg(b + kRespError, 1, "r", "IO-Link error code (0x80xx), 0 if ok")},
        {"isdu_response_length", reg(b + kRespLength, 1, "r", "octets of answer data")},
        {"isdu_response_data", reg(b + kRespData, kIsduDataCount, "r", "answer octets")},
        {"device_status", reg(b + kDeviceStatus, 1, "r", "index 36: 0 OK .. 4 failure")},
        {"event_count", reg(b + kEventCount, 1, "r", "pending events (index 37 entries), at most 16")},
        {"event_changes", reg(b + kEventChanges, 1, "r", "+1 whenever the pending events change")},
        {"events", reg(b + kEvents, 2 * kEventSlots, "r", "16 x (event qualifier, event code)")}});
  }
  return j;
}

} // namespace sreh::serve::modbus
