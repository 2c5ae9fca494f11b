// The SREH-50-IOL firmware as a value a caller drives (style.md 1, 2):
//   exchange()  once per IO-Link cycle: process data out in, process data in out;
//   tick()      once per control step: sensor readings in, motor command out;
//   isdu_read() / isdu_write(): acyclic parameter access (manual chapter 6);
//   power_off() / power_on(): supply interruption, non-volatile memory kept.
// No clocks, no files, no MuJoCo: time only advances through tick(dt).
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "device_logic/device_types.hpp"
#include "device_logic/isdu.hpp"
#include "device_logic/process_data.hpp"

namespace sreh {

// The non-volatile memory image: configuration and persistent diagnostics
// (manual 6.2, 6.3). A power cycle keeps it; the twin may save it to a file.
struct NonVolatileMemory;

class Device {
 public:
  Device();                                   // factory-new, powered on
  explicit Device(const std::vector<uint8_t>& nvm_image); // powered on with a saved memory image
  ~Device();
  Device(const Device&);
  Device& operator=(const Device&);

  // One IO-Link cycle. `outputs_valid` false: the master marked the outputs
  // invalid (manual 5). Returns nothing when the device does not communicate
  // (powered off, or after Back-To-Box until the next power cycle).
  std::optional<PdInFrame> exchange(const PdOutFrame& out, bool outputs_valid = true);

  // One control step of dt_s seconds. Also runs the communication watchdog:
  // no exchange() for longer than the watchdog time is a link loss (manual 5).
  MotorCommand tick(double dt_s, const SensorReadings& sensors);

  IsduResult isdu_read(uint16_t index, uint8_t subindex);
  IsduResult isdu_write(uint16_t index, uint8_t subindex, std::span<const uint8_t> data);

  // Supply interruption: off loses everything volatile; on re-reads the
  // multiturn encoder within +-720 deg (manual 4.1) and re-initialises.
  void power_off();
  void power_on(const SensorReadings& sensors);
  bool powered() const;

  std::vector<uint8_t> save_nvm() const;     // memory image, for a file
  Telemetry telemetry() const;
  LedColor led() const;                      // LED band now (blinking resolved)
  IoLinkLedMode io_link_led() const;
  bool in_boot_mode() const;                 // manual 9

  // Manual 9: in boot mode (system commands 80, 81, 82 in order) a master
  // transfers an update image. A valid image (see firmware_image()) restarts
  // the device in normal mode with its configuration kept; an invalid one
  // leaves it in boot mode, across power cycles, until a valid one arrives.
  // Returns 0 or an ISDU error code (0x8020 when not in boot mode, 0x8041 bad image).
  uint16_t firmware_update(std::span<const uint8_t> image);
  // A well-formed update image for `version` (format: A-FW-3).
  static std::vector<uint8_t> firmware_image(std::string_view version);

  struct Impl; // opaque: device_logic/device_impl.hpp

 private:
  std::unique_ptr<Impl> impl_;
};

} // namespace sreh
