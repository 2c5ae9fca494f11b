// IO-Link Data Storage at the master (manual 8 "Device exchange", iolink.md
// "Data Storage"): the master keeps a backup of a port's parameter set and
// puts it into a replacement module, so the PLC program runs on without
// re-parameterising. Through the device's own index 3 protocol
// (DS_Command, Index_List, Parameter_Checksum), exactly as a master does it
// over ISDU. Used by the scenario runner (`replace_device:`) and by serve's
// master (the caller holds the port lock there).
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "device_logic/data_storage.hpp"
#include "twin/twin.hpp"

namespace sreh {

struct DsBackup {
  uint32_t checksum = 0; // the device's Parameter_Checksum (3.4) after the upload
  struct Value {
    DsEntry entry;
    std::vector<uint8_t> data;
    bool operator==(const Value&) const = default;
  };
  std::vector<Value> values;
  bool operator==(const DsBackup&) const = default;
};

// Upload: UploadStart, Index_List, a read per entry, UploadEnd, checksum.
// Nothing (and the device left with Break) if the device refuses a step.
std::optional<DsBackup> ds_upload(Twin& twin);
// Download: DownloadStart, a write per entry, DownloadEnd (the device checks
// the set as a whole). 0, or the IO-Link code of the refused step (Break sent).
uint16_t ds_download(Twin& twin, const DsBackup& backup);

uint32_t ds_checksum(Twin& twin);    // 3.4; 0 if unreadable
bool ds_upload_requested(Twin& twin); // 3.2 bit 7

} // namespace sreh
