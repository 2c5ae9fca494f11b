#include "scenarios/data_storage_master.hpp"

#include "device_logic/parameter_store.hpp"

namespace sreh {
namespace {

bool command(Twin& twin, DsCommand c) {
  const uint8_t data[1] = {static_cast<uint8_t>(c)};
  return twin.isdu_write(kIndexDataStorage, 1, data).ok();
}

uint32_t read_u32(Twin& twin, uint8_t sub) {
  const IsduResult r = twin.isdu_read(kIndexDataStorage, sub);
  if (!r.ok()) return 0;
  uint32_t v = 0;
  for (uint8_t b : r.data) v = (v << 8) | b;
  return v;
}

} // namespace

uint32_t ds_checksum(Twin& twin) { return read_u32(twin, 4); }

bool ds_upload_requested(Twin& twin) {
  const IsduResult r = twin.isdu_read(kIndexDataStorage, 2);
  return r.ok() && !r.data.empty() && (r.data.back() & 0x80) != 0;
}

std::optional<DsBackup> ds_upload(Twin& twin) {
  if (!command(twin, DsCommand::UploadStart)) return std::nullopt;
  const IsduResult list = twin.isdu_read(kIndexDataStorage, 5);
  const auto entries = list.ok() ? decode_index_list(list.data) : std::nullopt;
  if (!entries) {
    command(twin, DsCommand::Break);
    return std::nullopt;
  }
  DsBackup b;
  for (const DsEntry& e : *entries) {
    const IsduResult r = twin.isdu_read(e.index, e.subindex);
    if (!r.ok()) {
      command(twin, DsCommand::Break);
      return std::nullopt;
    }
    b.values.push_back({e, r.data});
  }
  if (!command(twin, DsCommand::UploadEnd)) return std::nullopt;
  b.checksum = ds_checksum(twin);
  return b;
}

uint16_t ds_download(Twin& twin, const DsBackup& backup) {
  const uint8_t start[1] = {static_cast<uint8_t>(DsCommand::DownloadStart)};
  if (const IsduResult r = twin.isdu_write(kIndexDataStorage, 1, start); !r.ok()) return r.error;
  for (const auto& v : backup.values) {
    const IsduResult r = twin.isdu_write(v.entry.index, v.entry.subindex, v.data);
    if (!r.ok()) {
      command(twin, DsCommand::Break);
      return r.error;
    }
  }
  const uint8_t end[1] = {static_cast<uint8_t>(DsCommand::DownloadEnd)};
  const IsduResult r = twin.isdu_write(kIndexDataStorage, 1, end);
  return r.ok() ? 0 : r.error;
}

} // namespace sreh
