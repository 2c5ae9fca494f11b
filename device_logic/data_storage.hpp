// IO-Link Data Storage (manual 8 "Device exchange", iolink.md "Data Storage"):
// which parameters a master backs up, how index 3 encodes them, and the
// checksum a master compares on start-up.
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace sreh {

struct DsEntry {
  uint16_t index;
  uint8_t subindex; // 0: the whole record / plain variable
  bool operator==(const DsEntry&) const = default;
};

// DS_Command values written to index 3.1.
enum class DsCommand : uint8_t { UploadStart = 1, UploadEnd = 2, DownloadStart = 3, DownloadEnd = 4, Break = 5 };
// State_Property bits 2..1 (index 3.2).
enum class DsState : uint8_t { Inactive = 0, Upload = 1, Download = 2 };

// The Data Storage set, ascending: every configuration index of manual 6.2
// (records whole, subindex 0) plus the writable tags 24..26 (A-PARAM-7).
// Derived from the parameter table, so a new config row joins automatically.
std::span<const DsEntry> data_storage_entries();

// Index 3.5 Index_List: per entry index (2 octets, big-endian) + subindex,
// terminated by index 0x0000 (2 octets).
std::vector<uint8_t> encode_index_list(std::span<const DsEntry> entries);
// Inverse, as a master reads it; nullopt if malformed or unterminated.
std::optional<std::vector<DsEntry>> decode_index_list(std::span<const uint8_t> bytes);

// Index 3.2: bit 7 DS upload request flag, bits 2..1 state.
uint8_t ds_state_property(DsState state, bool upload_requested);

// CRC-32 (IEEE 802.3, reflected 0xEDB88320, init and final xor 0xFFFFFFFF).
// Chain by passing the previous result as `crc`.
uint32_t crc32(std::span<const uint8_t> bytes, uint32_t crc = 0);

} // namespace sreh
