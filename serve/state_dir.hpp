// `serve --state-dir DIR` (issue 27): what a module keeps through a power
// cycle, kept through a restart of `serve`. Per port two files:
//   DIR/port<P>.nvm          the device's non-volatile memory image (stored
//                            parameters, data storage, persistent counters),
//                            byte for byte `Twin::save_nvm()`, so the same file
//                            works as a scenario's `device: {nvm_image: ...}`;
//   DIR/port<P>.flange.json  where the flange is (physical frame), which the
//                            module's absolute multiturn encoder reads back at
//                            power-on (manual 4.1);
//   DIR/port<P>.ds.json      the master's Data Storage backup of the port
//                            (scenarios/data_storage_master.hpp, manual 8).
// Each is written durably when it changes (a temporary, fsync, rename, fsync of
// the folder: on disk, also through a power loss, when save() returns);
// temporaries a killed run left behind are removed at start; a missing file
// is a factory-new module / a flange at 0; a corrupt one is bad input naming
// the file and is never overwritten. DIR/.lock (flock) keeps a second serve out.
#pragma once
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "serve/ds_backup_file.hpp"

namespace sreh::serve {

struct PortState {
  std::optional<std::vector<uint8_t>> nvm;  // none: factory-new
  std::optional<double> flange_angle_deg;   // none: the flange at 0
  std::optional<DsBackup> ds;               // none: the master holds no backup yet
  bool ds_download_owed = false;            // a replaced module still waits for the backup
};

class StateDir {
 public:
  // Throws std::invalid_argument: not a folder, or held by another serve.
  StateDir(std::string dir, int ports);
  ~StateDir();
  StateDir(const StateDir&) = delete;
  StateDir& operator=(const StateDir&) = delete;

  // Reads port p's files; throws std::invalid_argument naming a corrupt one.
  PortState load(int p);
  // Write what differs from the last load/save (durable; thread-safe per
  // port). `seq` orders the callers of save_nvm: an image older than the one
  // written last is skipped. Throw std::runtime_error naming the file and the
  // reason (ENOSPC, EIO, EROFS, ...) if it cannot be written (the old file
  // stays). True if a file was written. save_flange(..., force): written even
  // if unchanged (whether the folder takes writes again after a failure).
  bool save_nvm(int p, uint64_t seq, const std::vector<uint8_t>& nvm);
  bool save_flange(int p, double flange_angle_deg, bool force = false);

  // The master's backup, written when `generation` is newer than the last one written.
  bool save_ds(int p, const DsBackup& backup, bool download_owed, uint64_t generation);

  std::string nvm_path(int p) const;
  std::string flange_path(int p) const;
  std::string ds_path(int p) const;

  // Flange moves smaller than this are not worth a write (encoder dither at rest).
  static constexpr double kFlangeResolution_deg = 0.01;

 private:
  struct Saved {
    std::mutex mutex;
    std::optional<std::vector<uint8_t>> nvm;
    std::optional<double> flange_angle_deg;
    uint64_t ds_generation = 0;
    uint64_t seq = 0;
  };
  std::string dir_;
  int lock_fd_ = -1;
  std::vector<std::unique_ptr<Saved>> saved_;
};

// Whether `image` is a memory image the device takes back unchanged (the
// check a restart relies on; a corrupt image would otherwise start the
// device with error 114.1 and be overwritten).
bool nvm_image_sound(const std::vector<uint8_t>& image);

} // namespace sreh::serve
