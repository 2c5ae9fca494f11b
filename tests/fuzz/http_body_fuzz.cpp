// libFuzzer target (issue 27): the HTTP/MQTT JSON bodies (serve/port_api)
// on one port: process data out, parameter writes, faults. Input: one
// route byte, index (2 octets), subindex, then the body text. A body is
// either applied or refused with RequestError (400-class) / IsduRefused
// (an IO-Link code 0x80xx); a refused body changes nothing the twin keeps.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "serve/hub.hpp"
#include "serve/port_api.hpp"

namespace {
sreh::serve::Hub& hub() {
  static auto* h = new sreh::serve::Hub(std::vector<sreh::TwinConfig>(1), sreh::serve::HubOptions{}); // MuJoCo once
  return *h;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace sreh::serve;
  if (size < 4) return 0;
  const uint8_t route = data[0] % 3;
  const auto index = static_cast<uint16_t>(data[1] << 8 | data[2]);
  const uint8_t sub = data[3];
  const std::string text(reinterpret_cast<const char*>(data + 4), size - 4);
  hub().with_port(1, [&](Hub::Port& port) {
    const std::vector<uint8_t> nvm_before = port.twin.save_nvm();
    const std::string pd_before = processdata_json(port)["out"].dump();
    const std::string faults_before = faults_json(port).dump();
    try {
      const Json body = parse_body(text);
      if (route == 0) apply_pd_out(port, body);
      else if (route == 1) write_parameter(port, index, sub, body);
      else if (!body.contains("replace_device") && !body.contains("power_cycle")) apply_faults(port, body);
    } catch (const RequestError& e) {
      if (e.status < 400 || e.status > 499) std::abort();
      if (port.twin.save_nvm() != nvm_before || processdata_json(port)["out"].dump() != pd_before ||
          faults_json(port).dump() != faults_before)
        std::abort(); // refused before it reached the twin
    } catch (const IsduRefused& e) {
      if ((e.code & 0xFF00) != 0x8000) std::abort();
    }
  });
  return 0;
}
