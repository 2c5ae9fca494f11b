// Firmware update (manual 9, IO-Link Firmware Update profile): boot mode,
// the image transfer over ISDU in chunks (A-FW-4) and image acceptance.
// Image format (A-FW-3): "IOLFW" + version text [+ 0x00 + filler] + CRC-32
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

std::vector<uint8_t> Device::firmware_image(std::string_view version, std::size_t size_B) {
  std::vector<uint8_t> out;
  out.reserve(std::max(size_B, sizeof kMagic + version.size() + 4));
  for (uint8_t b : kMagic) out.push_back(b);
  for (char c : version) out.push_back(static_cast<uint8_t>(c));
  if (size_B > out.size() + 4) {
    out.push_back(0); // end of the version text; the rest stands for the program
    uint32_t x = 0x2545F491u;
    while (out.size() < size_B - 4) {
      x ^= x << 13, x ^= x >> 17, x ^= x << 5; // deterministic filler
      out.push_back(static_cast<uint8_t>(x));
    }
  }
  const uint32_t crc = crc32(out);
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<uint8_t>(crc >> shift));
  return out;
}

// A-FW-4: subindex 1 appends a chunk (1..232 octets); subindex 2: 0 starts
// a new transfer, 1 ends it (the image is checked, then the device restarts).
uint16_t Device::Impl::firmware_write(uint8_t sub, std::span<const uint8_t> data) {
  if (sub != kFirmwareChunkSub && sub != kFirmwareCommandSub) return kIsduSubindexNotAvailable;
  if (!st.boot_mode) return kIsduServiceTempUnavailable; // manual 9: only in boot mode
  if (data.empty()) return kIsduLengthUnderrun;
  if (sub == kFirmwareChunkSub) {
    if (data.size() > Device::kFirmwareChunk_B) return kIsduLengthOverrun;
    if (st.fw_image.size() + data.size() > kFirmwareMaxImage) return kIsduValueOutOfRange;
    // The first chunk overwrites the application: from now on the module
    // only starts in boot mode until a good image is complete (manual 9).
    config.firmware_failed = true;
    st.fw_image.insert(st.fw_image.end(), data.begin(), data.end());
    return 0;
  }
  if (data.size() > 1) return kIsduLengthOverrun;
  switch (data[0]) {
    case kFirmwareCommandStart:
      st.fw_image.clear();
      return 0;
    case kFirmwareCommandEnd: {
      const bool good = image_valid(st.fw_image);
      st.fw_image.clear();
      // A bad image is refused and changes nothing more: if a chunk came,
      // the first one already marked the application erased (boot mode from
      // now on, manual 9); without any chunk the application is untouched.
      if (!good) return kIsduInconsistentParameterSet;
      config.firmware_failed = false;
      // Restart in normal mode; the configuration is kept (manual 9).
      SensorReadings s;
      s.encoder_counts = st.encoder;
      s.supply_V = st.supply_V;
      s.temperature_C = st.temperature_C;
      power_on(s);
      return 0;
    }
    default:
      return kIsduValueOutOfRange;
  }
}

uint16_t Device::firmware_update(std::span<const uint8_t> image) {
  Impl& d = *impl_;
  if (!d.st.powered || !d.st.boot_mode) return kIsduServiceTempUnavailable;
  const uint8_t start = kFirmwareCommandStart;
  const uint8_t end = kFirmwareCommandEnd;
  if (const uint16_t e = d.firmware_write(kFirmwareCommandSub, {&start, 1})) return e;
  for (std::size_t at = 0; at < image.size(); at += kFirmwareChunk_B) {
    const auto chunk = image.subspan(at, std::min(kFirmwareChunk_B, image.size() - at));
    if (const uint16_t e = d.firmware_write(kFirmwareChunkSub, chunk)) return e;
  }
  return d.firmware_write(kFirmwareCommandSub, {&end, 1});
}

} // namespace sreh
