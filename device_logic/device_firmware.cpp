// Firmware update (manual 9, IO-Link Firmware Update profile): boot mode and
// image acceptance. Image format (A-FW-3): "IOLFW" + version text + CRC-32
// (big-endian) of everything before it.
#include <algorithm>

#include "device_logic/data_storage.hpp"
#include "device_logic/device_impl.hpp"

namespace sreh {
namespace {
constexpr uint8_t kMagic[5] = {'I', 'O', 'L', 'F', 'W'};

bool image_valid(std::span<const uint8_t> image) {
  if (image.size() < sizeof kMagic + 4 || !std::equal(kMagic, kMagic + 5, image.begin())) return false;
  const auto body = image.first(image.size() - 4);
  const auto tail = image.last(4);
  const uint32_t want = (uint32_t{tail[0]} << 24) | (uint32_t{tail[1]} << 16) | (uint32_t{tail[2]} << 8) | tail[3];
  return crc32(body) == want;
}
} // namespace

std::vector<uint8_t> Device::firmware_image(std::string_view version) {
  std::vector<uint8_t> out;
  out.reserve(sizeof kMagic + version.size() + 4);
  for (uint8_t b : kMagic) out.push_back(b);
  for (char c : version) out.push_back(static_cast<uint8_t>(c));
  const uint32_t crc = crc32(out);
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<uint8_t>(crc >> shift));
  return out;
}

uint16_t Device::firmware_update(std::span<const uint8_t> image) {
  Impl& d = *impl_;
  if (!d.powered || !d.boot_mode) return kIsduServiceTempUnavailable;
  if (!image_valid(image)) {
    d.firmware_failed = true; // manual 9: from now on only boot mode
    return kIsduInconsistentParameterSet;
  }
  d.firmware_failed = false;
  // Restart in normal mode; the configuration is kept (manual 9).
  SensorReadings s;
  s.encoder_counts = d.encoder;
  s.supply_V = d.supply_V;
  s.temperature_C = d.temperature_C;
  d.power_on(s);
  return 0;
}

} // namespace sreh
