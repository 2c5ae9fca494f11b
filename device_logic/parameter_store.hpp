// The device's stored parameters (manual 6.2 configuration, 6.3 persistent
// diagnostics, 6.5 identification incl. tags, 8 Data Storage index 3) with
// ISDU access, block parameterisation (6.6 commands 1..6) and the
// non-volatile memory image. Ranges and defaults come only from the
// parameter table. No exceptions, no I/O: pure device logic.
//
// The Device answers volatile diagnostics (32, 36, 37, 40, 41, 112..115,
// 17343) and its own system commands (80..83, 126..131, 160..171) itself and
// routes every other ISDU request here.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "device_logic/data_storage.hpp"
#include "device_logic/isdu.hpp"
#include "device_logic/parameter_ids.hpp"

namespace sreh {

// Motion parameter set n = index 64 + n (manual 3.5, 6.2) in display units.
struct MotionParameterSet {
  double speed_dps;           // 64+n.1
  double accel_pct;           // 64+n.2
  double jerk_pct;            // 64+n.3
  double load_gcm2;           // 64+n.4
  double tolerance_deg;       // 64+n.5 (raw 2^-19 rev)
  double wait_ms;             // 64+n.6
  double settling_timeout_ms; // 64+n.7
  bool timeout_enabled;       // 64+n.8
};

// Block parameterisation system commands (index 2, manual 6.6, iolink.md).
inline constexpr uint8_t kCmdParamUploadStart = 1;
inline constexpr uint8_t kCmdParamUploadEnd = 2;
inline constexpr uint8_t kCmdParamDownloadStart = 3;
inline constexpr uint8_t kCmdParamDownloadEnd = 4;
inline constexpr uint8_t kCmdParamDownloadStore = 5;
inline constexpr uint8_t kCmdParamBreak = 6;

inline constexpr uint16_t kIndexSystemCommand = 2;
inline constexpr uint16_t kIndexDataStorage = 3;

class ParameterStore {
 public:
  ParameterStore(); // factory defaults (manual 6.2), identification per 6.5

  // ISDU access. Subindex 0 on a record = all members concatenated big-endian
  // in subindex order. Errors (isdu.hpp): 0x8011 index, 0x8012 subindex,
  // 0x8023 access, 0x8030 range, 0x8033/0x8034 length, 0x8035 unknown system
  // command, 0x8036 command at the wrong moment, 0x8040 a single write
  // collides (81.1 > 81.2), 0x8041 block download inconsistent.
  // Rows the Device answers (volatile diagnostics) read as 0x8020 here.
  // A refused write changes nothing. During an open download, writes are
  // buffered and reads return the applied values (A-PARAM-8).
  IsduResult read(uint16_t index, uint8_t subindex) const;
  IsduResult write(uint16_t index, uint8_t subindex, std::span<const uint8_t> data);

  // System commands 1..6 (block parameterisation): 0 or an ISDU error code;
  // any other value 0x8035.
  uint16_t block_command(uint8_t cmd);
  bool download_open() const;
  bool upload_open() const;
  // Communication loss / any reset: an open download is discarded, an open
  // upload and Data Storage sequence end (iolink.md).
  void abort_block();

  // keep_tags true = 129 Application reset: configuration to defaults, tags
  // and identification kept, DS upload requested. false = 130/131 Restore
  // factory / Back-to-box: tags too, DS upload request cleared.
  // Persistent diagnostics are never reset here (manual 6.3; 160/161 reset
  // 99 and 100 through set_raw_internal).
  void factory_reset(bool keep_tags);

  // Typed accessors, O(1).
  MotionParameterSet motion_set(int n) const; // n 0..7 (clamped)
  // Raw numeric value of a config / persistent row (table default for other
  // numeric rows, 0 for unknown or non-numeric rows).
  int64_t raw(uint16_t index, uint8_t subindex) const;
  int64_t raw(ParamId id) const { return raw(id.index, id.subindex); }
  // Device-side update, no access checks, clamped to the row's range: the
  // persistent counters 96..100, 86 via command 171. Changing a config row
  // counts as a local change: config revision advances and a DS upload is
  // requested (iolink.md). Unknown or non-numeric rows are ignored.
  void set_raw_internal(uint16_t index, uint8_t subindex, int64_t raw);
  void set_raw_internal(ParamId id, int64_t raw) { set_raw_internal(id.index, id.subindex, raw); }
  std::string tag(uint16_t index) const; // 24, 25, 26 (empty for others)

  // Non-volatile memory image: config, persistent diagnostics, tags and the
  // DS upload flag; magic, version and CRC-32. from_image refuses a corrupt
  // or incompatible image (bad magic/version/CRC, unknown or volatile row,
  // wrong length, value out of range, inconsistent set).
  std::vector<uint8_t> image() const;
  static std::optional<ParameterStore> from_image(std::span<const uint8_t> bytes);

  // Data Storage (index 3).
  uint32_t parameter_checksum() const; // 3.4: CRC-32 over the DS set
  uint32_t data_storage_size() const;  // 3.3
  bool ds_upload_requested() const;
  void clear_ds_upload_request();
  void request_ds_upload();
  DsState ds_state() const;

  // Increments on every applied change of the DS set (config or tags).
  uint64_t config_revision() const;

  // Same configuration and tags (what Data Storage carries).
  bool same_configuration(const ParameterStore& other) const;
  // Everything observable: all stored values, open download buffer, upload /
  // DS state and the DS upload flag. The revision counter is not compared.
  bool operator==(const ParameterStore& other) const;

 private:
  static constexpr std::size_t kTagCount = 3; // indices 24, 25, 26
  struct Values {
    std::vector<int64_t> numeric;          // by parameter table row position
    std::array<std::string, kTagCount> tags;
    bool operator==(const Values&) const = default;
  };

  IsduResult read_from(const Values& v, uint16_t index, uint8_t subindex) const;
  uint16_t write_record(uint16_t index, std::span<const uint8_t> data);
  uint16_t write_row(uint16_t index, uint8_t subindex, std::span<const uint8_t> data);
  uint16_t ds_command(uint8_t cmd);
  // Applies `next` (already value-checked) to the buffer or, outside a
  // download, to the active set after the cross-parameter check.
  uint16_t commit_single(Values next);
  uint16_t end_download(); // ParamDownloadEnd / DS DownloadEnd
  void discard_download();  // ParamBreak / ParamUploadEnd: buffer dropped
  Values& target();        // pending buffer if a download is open, else active
  void apply(Values next);
  std::vector<uint8_t> ds_set_bytes() const;

  Values active_;
  std::optional<Values> pending_; // open block / DS download buffer
  bool upload_open_ = false;
  DsState ds_state_ = DsState::Inactive;
  bool ds_upload_flag_ = false;
  uint64_t revision_ = 0;
};

} // namespace sreh
