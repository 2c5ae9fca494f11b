// Master side of a firmware update (manual 9): the image as a sequence of
// ISDU writes to the device's firmware data object (A-FW-4), and how many
// master cycles each write takes on the wire (A-FW-5). Shared by
// Twin::firmware_update() and the scenario runner, which runs the cycles
// itself so that traces, checks and videos see the whole transfer.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace sreh {

struct IsduWriteRequest {
  uint16_t index = 0;
  uint8_t subindex = 0;
  std::vector<uint8_t> data;
  std::size_t image_octets_after = 0; // image octets transferred once this write is done
};

// Start command, chunks of at most Device::kFirmwareChunk_B octets, end command.
std::vector<IsduWriteRequest> firmware_requests(std::span<const uint8_t> image);

// A-FW-5: the on-request channel carries 2 octets per master cycle (TYPE_2_V,
// OD 2); a write of n data octets sends n + 6 octets (I-Service, ExtLength,
// Index x2, Subindex, CHKPDU) and receives 2, so it takes ceil((n + 8) / 2)
// cycles. 232 octets: 120 cycles, 0.24 s at 2 ms; a 256 KiB image ~4.5 min.
uint64_t isdu_write_cycles(std::size_t data_octets);

} // namespace sreh
