// The Device's insides (docs/style.md 2): the three parts of a DeviceSnapshot
// held as members (`config` non-volatile, `st` volatile, `mon` the monitors'
// memories) plus the firmware's functions. A function that needs one part
// (or a few fields) takes it as an argument, so its signature says what it
// touches; the Impl's own methods are the ones that act across the parts
// (the state machine, the control step, ISDU routing).
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "device_logic/device.hpp"
#include "device_logic/device_snapshot.hpp"
#include "device_logic/motor_model.hpp"
#include "device_logic/state_machine.hpp"

namespace sreh {

// Firmware transfer over ISDU (A-FW-4): the image arrives in chunks at
// index 17344 subindex 1; subindex 2 takes the transfer commands.
inline constexpr uint8_t kFirmwareChunkSub = 1;
inline constexpr uint8_t kFirmwareCommandSub = 2;
inline constexpr uint8_t kFirmwareCommandStart = 0;
inline constexpr uint8_t kFirmwareCommandEnd = 1;
inline constexpr std::size_t kFirmwareMaxImage = 4u << 20; // 4 MiB: far above any module image

// Boot mode status, index 17343 (A-FW-1).
enum class BootStatus : uint8_t { Normal = 0, BootMode = 1, BootModeAfterFailedUpdate = 2 };

struct Device::Impl {
  DeviceConfiguration config; // non-volatile, with the constant drive model
  DeviceState st;             // volatile
  DeviceMonitors mon;         // volatile

  explicit Impl(const DriveModel& d) { config.drive = d; } // power_on() then builds the controller from it
  explicit Impl(const DeviceSnapshot& s) : config(s.configuration), st(s.state), mon(s.monitors) {}
  DeviceSnapshot snapshot() const { return {config, st, mon}; }

  // device.cpp: power, process data, state machine
  void power_on(const SensorReadings& s);
  void process_outputs(const ProcessDataOut& next);
  void apply(Event e);
  void raise_error(ErrorBit bit, uint8_t code);
  void enter(State to, Event via);
  bool motor_on() const { return motor_is_on(st.state); }
  int64_t user_now() const;
  void init_origin();
  std::optional<ErrorBit> prepare_move(const ProcessDataOut& cmd, uint8_t& code);
  MotorCommand tick(int64_t dt_ns, const SensorReadings& sensors);

  // device_motion.cpp: the control step and the move records
  void start_move();
  MotorCommand control(int64_t dt_ns, double dt_s); // dt_s = dt_ns / 1e9, derived once per tick
  double user_deg(int64_t phys_counts) const;     // process-data degrees of a physical position
  double setpoint_user_deg() const;               // the setpoint now, process-data degrees
  void record_move_step();                        // the move recorder's control step

  // device_monitors.cpp
  void run_monitors(int64_t dt_ns);
  void link_lost();

  // device_isdu.cpp
  IsduResult read(uint16_t index, uint8_t subindex) const;
  IsduResult write(uint16_t index, uint8_t subindex, std::span<const uint8_t> data);
  uint16_t system_command(uint8_t cmd);
  uint16_t firmware_write(uint8_t sub, std::span<const uint8_t> data); // device_firmware.cpp
};

// device.cpp. Manual 2.3: the process data in of `st` at `user_counts`
// (the position in the process-data frame, Impl::user_now()).
ProcessDataIn pd_in(const DeviceState& st, int64_t user_counts);

// device_motion.cpp. A-SM-6: tunes the loop for motion set `set_number` of
// `store` (limits, inertia, hold_set); an invalid number changes nothing.
void tune_for_set(DeviceState& st, const ParameterStore& store, uint8_t set_number);
// T4 and T8.1: the stop profile from the setpoint's state now (manual 3.2).
void start_stop_profile(DeviceState& st);

// device_monitors.cpp. Manual 6.3: the operating times (97, 100) and
// maximum temperatures (98, 99) in `store`, one control step on.
void run_diagnostics(DiagnosticsClock& clock, ParameterStore& store, const DeviceState& st, int64_t dt_ns);
// Manual 6.2 index 87.1 in degrees (A-PARAM-1).
double tracking_limit_deg(const ParameterStore& store);
// The LED band now (manual 3.1, 6.2 index 83, 6.6 locator, 9 boot mode).
LedColor led_color(const DeviceState& st, const Locator& locator, const ParameterStore& store);

// device_nvm.cpp: the memory image is the ParameterStore's image plus the
// firmware-update state (manual 9), framed and versioned.
std::vector<uint8_t> save_nvm_image(const DeviceConfiguration& c);
bool restore_nvm(DeviceConfiguration& c, const std::vector<uint8_t>& image);

} // namespace sreh
