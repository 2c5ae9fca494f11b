// Private state of the Device (style.md 2): the ParameterStore is the
// non-volatile part; everything else here is volatile and lost on power-off.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "device_logic/device.hpp"
#include "device_logic/faults.hpp"
#include "device_logic/motor_model.hpp"
#include "device_logic/move_record.hpp"
#include "device_logic/parameter_store.hpp"
#include "device_logic/planner.hpp"
#include "device_logic/position_controller.hpp"
#include "device_logic/settling.hpp"
#include "device_logic/state_machine.hpp"

namespace sreh {

// Timing of monitors and the watchdog; see ASSUMPTIONS.md.
inline constexpr int64_t kNsPerS = 1'000'000'000;
inline constexpr int64_t kLinkWatchdogMin_ns = 20'000'000;   // A-LINK-1: at least 20 ms ...
inline constexpr int kLinkWatchdogCycles = 3;                 // ... and at least 3 master cycles
inline constexpr int64_t kDefaultMasterCycle_ns = 2'000'000;  // manual 1: minimum cycle time 2 ms
inline constexpr int64_t kVoltageDebounce_ns = 2'000'000;    // A-MON-1
inline constexpr double kTemperatureWarning_C = 70.0;        // manual 7.3 (>= 70 C)
inline constexpr double kTemperatureError_C = 75.0;          // manual 7.2 (>= 75 C)
inline constexpr double kTemperatureHysteresis_C = 1.0;      // A-MON-2
inline constexpr int64_t kLocatorDuration_ns = 600 * kNsPerS; // manual 6.6: 10 minutes
inline constexpr int64_t kMinute_ns = 60 * kNsPerS;
inline constexpr double kTrackingErrorRawUnit_deg = 0.1;      // A-PARAM-1: raw unit of index 87.1
inline constexpr double kVelocityFilter_s = 0.001;           // A-MON-3: telemetry / torque-limit speed filter

enum class MotionPhase : uint8_t { Hold, Travel, Settle };

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
  // --- non-volatile ---
  ParameterStore store;
  bool firmware_failed = false; // manual 9: a failed update starts in boot mode until a good image

  // --- constant ---
  MotorModel motor;

  // --- volatile ---
  bool powered = true;
  bool comm_blocked = false;  // Back-To-Box until the next power cycle (manual 6.6, 131)
  bool boot_mode = false;
  uint8_t fw_unlock_step = 0; // system commands 80, 81, 82 in order
  std::vector<uint8_t> fw_image; // firmware chunks received so far (A-FW-4)
  ComPhase com_phase = ComPhase::Startup; // IO-Link start-up after power-on (A-LINK-3)
  int64_t master_cycle_ns = kDefaultMasterCycle_ns; // MasterCycleTime the master announced (A-LINK-1)
  int64_t time_ns = 0;        // since power-on
  int64_t since_exchange_ns = 0;
  bool link_up = false;       // cycles arriving (watchdog not expired)
  bool outputs_valid = false;
  ProcessDataOut pd{};        // last valid process data out acted upon
  PdOutFrame last_out_frame{};
  PdInFrame last_in_frame{};

  State state = State::MotorOff;
  FaultSet faults;
  uint16_t error_counter = 0;

  // position (manual 4)
  int64_t encoder = 0;
  int64_t origin = 0;
  double supply_V = 24.0;
  double temperature_C = 25.0;

  // motion
  MotionPhase phase = MotionPhase::Hold;
  Profile profile;
  double profile_t_s = 0;
  int64_t start_phys = 0;    // encoder counts where the trajectory starts
  int64_t target_phys = 0;   // where it ends (exact)
  int64_t hold_phys = 0;     // setpoint when not travelling
  MotionLimits limits{};
  double inertia_kgm2 = 0;
  SettlingParameters settle{};
  SettlingMonitor settling;
  PositionController controller;
  std::optional<int64_t> last_target_phys; // manual 3.4 relative moves
  bool positioned = false;   // completed positioning, window watched for 115.3
  uint32_t moves_started = 0; // T3 since power-on (telemetry)
  KinematicState setpoint{}; // physical rad, this step
  double stop_base_rad = 0;  // profile positions are relative to this
  int64_t prev_encoder = 0;
  double velocity_rad_s = 0; // filtered encoder speed, physical frame
  double torque_Nm = 0;
  double torque_limit_Nm = 0;

  // monitors
  int64_t voltage_out_ns = 0;
  uint8_t voltage_cause = 0;

  // diagnostics (manual 6.3): sub-minute remainders
  int64_t powered_rem_ns = 0, motor_on_rem_ns = 0, moving_rem_ns = 0, temp_warn_rem_ns = 0;

  // move records (issue 13): built here, where the set was latched
  MoveRecorder move_recorder;
  double peak_tracking_error_deg = 0; // max |setpoint - encoder| since the last take (motor on)
  double step_tracking_error_deg = 0; // |setpoint - encoder| of this control step (0 with the motor off)

  // locator (manual 6.6, 126/127)
  bool locator = false;
  int64_t locator_start_ns = 0;

  Impl();
  explicit Impl(ParameterStore s);

  // device.cpp
  void power_on(const SensorReadings& s);
  void process_outputs(const ProcessDataOut& next);
  void apply(Event e);
  void raise_error(ErrorBit bit, uint8_t code);
  void set_warning(WarningBit bit, uint8_t code) { faults.warning_cause[static_cast<int>(bit)] = code; }
  void enter(State to, Event via);
  bool motor_on() const { return (kMotorOnStates & state_bit(state)) != 0; }
  int dir() const { return store.raw(82, 0) == 1 ? -1 : 1; }
  int64_t user_now() const;
  void init_origin();
  std::optional<ErrorBit> prepare_move(const ProcessDataOut& cmd, uint8_t& code);
  void start_stop_profile();
  void run_monitors(int64_t dt_ns);
  void run_diagnostics(int64_t dt_ns);
  MotorCommand control(double dt_s);
  ProcessDataIn pd_in() const;
  double user_deg(int64_t phys_counts) const;     // process-data degrees of a physical position
  double setpoint_user_deg() const;               // the setpoint now, process-data degrees
  void record_move_step();                        // the move recorder's control step
  LedColor led() const;
  double tracking_limit_deg() const;

  // device_isdu.cpp
  IsduResult read(uint16_t index, uint8_t subindex) const;
  IsduResult write(uint16_t index, uint8_t subindex, std::span<const uint8_t> data);
  uint16_t system_command(uint8_t cmd);
  uint16_t firmware_write(uint8_t sub, std::span<const uint8_t> data); // device_firmware.cpp
  int64_t watchdog_ns() const;
  uint8_t device_status() const;
  std::vector<uint8_t> detailed_device_status() const;

  // motion set latched on Move (manual 3.2 T3)
  ProcessDataOut latched{};
  int64_t pending_target_phys = 0;
};

// device_nvm.cpp: the memory image is the ParameterStore's image plus the
// firmware-update state (manual 9), framed and versioned.
std::vector<uint8_t> save_nvm_image(const Device::Impl& d);
bool restore_nvm(Device::Impl& d, const std::vector<uint8_t>& image);

} // namespace sreh
