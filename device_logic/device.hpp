// The SREH-50-IOL firmware as a value a caller drives (docs/style.md 1, 2):
//   exchange()  once per IO-Link cycle: process data out in, process data in out;
//   tick()      once per control step: sensor readings in, motor command out;
//   isdu_read() / isdu_write(): acyclic parameter access (manual chapter 6);
//   power_off() / power_on(): supply interruption, non-volatile memory kept.
//   snapshot() / restore(): the whole device as a value (device_snapshot.hpp).
// No clocks, no files, no MuJoCo: time only advances through tick(dt), in
// integer nanoseconds.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "device_logic/device_types.hpp"
#include "device_logic/isdu.hpp"
#include "device_logic/move_record.hpp"
#include "device_logic/process_data.hpp"

namespace sreh {

// Defined in device_logic/drive_model.hpp and device_snapshot.hpp: include
// those where a drive model is built or a snapshot is looked into. This
// header names them only, so a user of Device does not compile the
// firmware's insides.
struct DriveModel;
struct DeviceSnapshot;

// The non-volatile memory image: configuration and persistent diagnostics
// (manual 6.2, 6.3). A power cycle keeps it; the twin may save it to a file.
struct NonVolatileMemory;

class Device {
 public:
  // The drive's data come from the module's model card (drive_model.hpp).
  explicit Device(const DriveModel& drive);   // factory-new, powered on
  Device(const DriveModel& drive, const std::vector<uint8_t>& nvm_image); // powered on with a saved memory image
  explicit Device(const DeviceSnapshot& snapshot);         // exactly where the snapshot was taken
  ~Device();
  Device(const Device&);
  Device& operator=(const Device&);

  // One IO-Link cycle. `outputs_valid` false: the master marked the outputs
  // invalid (manual 5). Returns nothing when the device does not communicate
  // (powered off, or after Back-To-Box until the next power cycle).
  std::optional<PdInFrame> exchange(const PdOutFrame& out, bool outputs_valid = true);

  // One master cycle before OPERATE (IO-Link STARTUP or PREOPERATE): on-request
  // data only, no process data; feeds the watchdog and sets the IO-Link LED
  // (manual 1). After every power-on the device is in STARTUP until the master
  // moves it on; exchange() is OPERATE. false: the device does not communicate.
  bool startup_cycle(ComPhase phase);
  ComPhase com_phase() const;

  // The master's cycle time as the master announces it (IO-Link direct
  // parameter MasterCycleTime, written during start-up). The link watchdog is
  // max(20 ms, 3 master cycles) (A-LINK-1). Volatile: 2 ms after power-on
  // until the master writes it again.
  void set_master_cycle_time(double cycle_s);

  // One control step of dt_s seconds. Also runs the communication watchdog:
  // no exchange() for longer than the watchdog time is a link loss (manual 5).
  // The device keeps time in integer nanoseconds only: dt_s is converted
  // once, rounded to the nearest ns (0.1 ms -> 100'000 ns exactly); a
  // negative or non-finite dt_s counts as 0. tick_ns() takes the ns directly.
  MotorCommand tick(double dt_s, const SensorReadings& sensors);
  MotorCommand tick_ns(int64_t dt_ns, const SensorReadings& sensors);

  IsduResult isdu_read(uint16_t index, uint8_t subindex);
  IsduResult isdu_write(uint16_t index, uint8_t subindex, std::span<const uint8_t> data);

  // Supply interruption: off loses everything volatile; on re-reads the
  // multiturn encoder within +-720 deg (manual 4.1) and re-initialises.
  void power_off();
  void power_on(const SensorReadings& sensors);
  bool powered() const;

  std::vector<uint8_t> save_nvm() const;     // memory image, for a file

  // The whole device as a value: configuration, volatile state, monitors.
  // A device restored from a snapshot (or constructed from one) continues
  // bit for bit as the original would from that instant, move records not
  // yet handed out included. Compare snapshots with ==.
  DeviceSnapshot snapshot() const;
  void restore(const DeviceSnapshot& snapshot);

  // Move records (issue 13): one per accepted Move (T3), built by the device
  // on its own clock (start_ns: ns since its power-on). A record is handed out
  // once its move ended and the target is no longer held (next move, error,
  // motor off, power off); pending_move() is the open or held one.
  std::vector<MoveRecord> take_finished_moves();
  std::optional<MoveRecord> pending_move() const;
  // The largest |setpoint - encoder| of any control step with the motor on
  // since the last call (the one definition of the tracking error, issue 16).
  double take_peak_tracking_error_deg();
  Telemetry telemetry() const;
  LedColor led() const;                      // LED band now (blinking resolved)
  IoLinkLedMode io_link_led() const;
  bool in_boot_mode() const;                 // manual 9

  // Manual 9: in boot mode (system commands 80, 81, 82 in order) a master
  // transfers an update image over ISDU in chunks (A-FW-4: index 17344
  // subindex 1 the chunks, subindex 2 start 0 / end 1). From the first chunk
  // on the old application is gone: a power loss before a good image is
  // complete leaves the module in boot mode. A valid image (firmware_image())
  // restarts the device in normal mode with its configuration kept; an
  // invalid one leaves it in boot mode, across power cycles, until a valid
  // one arrives. firmware_update() is that whole sequence at once (no time
  // passes); returns 0 or an ISDU error code (0x8020 when not in boot mode,
  // 0x8041 bad image).
  uint16_t firmware_update(std::span<const uint8_t> image);
  // A well-formed update image for `version` (format: A-FW-3), padded with
  // `size_B - 9 - version.size()` filler octets to `size_B` octets when larger.
  static std::vector<uint8_t> firmware_image(std::string_view version, std::size_t size_B = 0);
  static constexpr uint16_t kFirmwareDataIndex = 17344; // A-FW-4
  static constexpr std::size_t kFirmwareChunk_B = 232;  // ISDU data maximum (IO-Link 1.1.3)

  struct Impl; // opaque: device_logic/device_impl.hpp

 private:
  std::unique_ptr<Impl> impl_;
};

} // namespace sreh
