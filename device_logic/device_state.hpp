// The volatile state of the Device: everything that defines its behaviour
// from one control step to the next and that a power cycle loses (manual
// 3.1 state machine, 2.4 faults, 4 position, 3.5 motion, the IO-Link link
// state). A plain value: copyable, comparable with ==, no behaviour; the
// firmware's functions (device.cpp) act on it. Time is integer nanoseconds.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "device_logic/device_types.hpp"
#include "device_logic/faults.hpp"
#include "device_logic/move_record.hpp"
#include "device_logic/planner.hpp"
#include "device_logic/position_controller.hpp"
#include "device_logic/process_data.hpp"
#include "device_logic/settling.hpp"

namespace sreh {

enum class MotionPhase : uint8_t { Hold, Travel, Settle };

struct DeviceState {
  // --- power, IO-Link, firmware update ---
  bool powered = true;
  bool comm_blocked = false;     // Back-To-Box until the next power cycle (manual 6.6, 131)
  bool boot_mode = false;        // manual 9
  uint8_t fw_unlock_step = 0;    // system commands 80, 81, 82 in order
  std::vector<uint8_t> fw_image; // firmware chunks received so far (A-FW-4)
  ComPhase com_phase = ComPhase::Startup; // IO-Link start-up after power-on (A-LINK-3)
  int64_t time_ns = 0;           // since power-on: the device's only clock
  bool outputs_valid = false;
  ProcessDataOut pd{};           // last valid process data out acted upon
  PdOutFrame last_out_frame{};
  PdInFrame last_in_frame{};
  ProcessDataOut latched{};      // the Move command latched at T3 (manual 3.2)
  int64_t pending_target_phys = 0; // its target, physical counts

  // --- state machine and faults (manual 3.1, 2.4) ---
  State state = State::MotorOff;
  FaultSet faults;
  uint16_t error_counter = 0;

  // --- sensors, position (manual 4) ---
  int64_t encoder = 0;           // physical internal counts
  int64_t prev_encoder = 0;
  int64_t origin = 0;
  double supply_V = 24.0;
  double temperature_C = 25.0;
  double velocity_rad_s = 0;     // filtered encoder speed, physical frame (A-MON-3)

  // --- motion (manual 3.4, 3.5) ---
  MotionPhase phase = MotionPhase::Hold;
  Profile profile;
  int64_t profile_ns = 0;        // time into `profile`: sampled at profile_ns / 1e9 s, never accumulated in float
  int64_t start_phys = 0;        // encoder counts where the trajectory starts
  int64_t target_phys = 0;       // where it ends (exact)
  int64_t hold_phys = 0;         // setpoint when not travelling
  double stop_base_rad = 0;      // profile positions are relative to this
  KinematicState setpoint{};     // physical rad, this step
  MotionLimits limits{};
  double inertia_kgm2 = 0;       // J_intern + the configured load the loop is tuned for
  uint8_t hold_set = 0;          // the set whose load tunes the loop while holding (A-SM-6)
  SettlingParameters settle{};
  SettlingMonitor settling;
  PositionController controller;
  double torque_Nm = 0;
  double torque_limit_Nm = 0;
  std::optional<int64_t> last_target_phys; // manual 3.4 relative moves
  bool positioned = false;       // completed positioning, window watched for 115.3
  uint32_t moves_started = 0;    // T3 since power-on (telemetry)
  MoveRecorder move_recorder;    // issue 13: records built where the set was latched

  bool operator==(const DeviceState&) const = default;
};

} // namespace sreh
