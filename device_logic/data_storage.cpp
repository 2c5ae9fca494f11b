// Data Storage set, index list codec and CRC-32 (manual 8, iolink.md).
#include "device_logic/data_storage.hpp"
#include "device_logic/byte_order.hpp"

#include <array>

#include "device_logic/parameter_table.hpp"

namespace sreh {
namespace {

std::vector<DsEntry> build_entries() {
  std::vector<DsEntry> entries;
  for (const auto& row : parameter_table()) {
    const bool config = row.storage == Storage::Config;
    const bool tag = row.storage == Storage::Identification && row.access == Access::RW;
    if (!config && !tag) continue;
    if (!entries.empty() && entries.back().index == row.index) continue; // a record: once, whole
    entries.push_back(DsEntry{row.index, 0});
  }
  return entries;
}

constexpr std::array<uint32_t, 256> kCrcTable = [] {
  std::array<uint32_t, 256> t{};
  for (uint32_t i = 0; i < 256; ++i) {
    uint32_t c = i;
    for (int k = 0; k < 8; ++k) c = (c & 1u) ? (0xEDB88320u ^ (c >> 1)) : (c >> 1);
    t[i] = c;
  }
  return t;
}();

} // namespace

std::span<const DsEntry> data_storage_entries() {
  static const std::vector<DsEntry> entries = build_entries();
  return entries;
}

std::vector<uint8_t> encode_index_list(std::span<const DsEntry> entries) {
  std::vector<uint8_t> out;
  out.reserve(entries.size() * 3 + 2);
  for (const auto& e : entries) {
    be::append16(out, e.index);
    out.push_back(e.subindex);
  }
  out.push_back(0);
  out.push_back(0);
  return out;
}

std::optional<std::vector<DsEntry>> decode_index_list(std::span<const uint8_t> bytes) {
  std::vector<DsEntry> entries;
  std::size_t i = 0;
  while (i + 2 <= bytes.size()) {
    const uint16_t index = be::read16(bytes, i);
    if (index == 0) return i + 2 == bytes.size() ? std::optional{entries} : std::nullopt;
    if (i + 3 > bytes.size()) return std::nullopt;
    entries.push_back(DsEntry{index, bytes[i + 2]});
    i += 3;
  }
  return std::nullopt; // no terminator
}

uint8_t ds_state_property(DsState state, bool upload_requested) {
  return static_cast<uint8_t>((upload_requested ? 0x80u : 0u) | (static_cast<unsigned>(state) << 1));
}

uint32_t crc32(std::span<const uint8_t> bytes, uint32_t crc) {
  uint32_t c = crc ^ 0xFFFFFFFFu;
  for (uint8_t b : bytes) c = kCrcTable[(c ^ b) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

} // namespace sreh
