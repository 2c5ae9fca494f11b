#include "twin/firmware_transfer.hpp"

#include <algorithm>

#include "device_logic/device.hpp"

namespace sreh {

std::vector<IsduWriteRequest> firmware_requests(std::span<const uint8_t> image) {
  constexpr uint16_t kIndex = Device::kFirmwareDataIndex;
  std::vector<IsduWriteRequest> out;
  out.push_back(IsduWriteRequest{kIndex, 2, {0}, 0}); // start
  for (std::size_t at = 0; at < image.size(); at += Device::kFirmwareChunk_B) {
    const std::size_t n = std::min(Device::kFirmwareChunk_B, image.size() - at);
    const auto chunk = image.subspan(at, n);
    out.push_back(IsduWriteRequest{kIndex, 1, {chunk.begin(), chunk.end()}, at + n});
  }
  out.push_back(IsduWriteRequest{kIndex, 2, {1}, image.size()}); // end: check and restart
  return out;
}

uint64_t isdu_write_cycles(std::size_t data_octets) { return (data_octets + 8 + 1) / 2; }

} // namespace sreh
