// A running twin as a value (issue 13): Twin::snapshot() hands one out,
// Twin::restore() takes it back, and the twin continues bit for bit as it
// did after the snapshot was taken (A-TWIN-34..36). Snapshots are
// immutable; copies share the MuJoCo state they hold.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "device_logic/device_snapshot.hpp"
#include "device_logic/device_types.hpp"
#include "device_logic/move_record.hpp"
#include "device_logic/process_data.hpp"
#include "twin/motor_drive.hpp"
#include "twin/specs.hpp"
#include "twin/supply.hpp"
#include "twin/thermal.hpp"
#include "twin/trace.hpp"

struct mjData_;

namespace sreh {

// The plant (twin/plant.hpp) beyond its compiled model: the whole mjData,
// the model fields the twin changes while it runs (MuJoCo 2.2.2 keeps the
// equality's eq_active / eq_data and the LED's colour in mjModel), the
// drive's current loop, the supply and the thermal nodes, its clocks.
struct PlantSnapshot {
  WorldSpec world;                     // the load then; the rest must match on restore
  std::shared_ptr<const mjData_> data; // mj_copyData of the plant's data, never written again
  bool flange_blocked = false;
  double block_angle_rad = 0;          // the equality's hold angle (eq_data[0])
  std::array<float, 4> led_rgba{};
  MotorDrive drive;
  Supply supply;
  Thermal thermal;
  double ghost_angle_rad = 0;
  double external_torque_Nm = 0;
  double applied_torque_Nm = 0;
  double torque_limit_Nm = 0;
  double electrical_power_W = 0;
  double copper_loss_W = 0;
  uint64_t steps = 0;
  SensorReadings sensors;
};

// What the twin itself keeps between cycles: the PLC and master side, the
// integer clocks, the hand turning the flange, what it collected. Twin::Impl
// is built on it, so a field added here is snapshotted without more code.
struct TwinRunState {
  int steps = 0;             // control periods per master cycle
  double cycle_s = 0;        // the master cycle now (as configured)
  ProcessDataOut pd_out{};
  bool outputs_valid = true;
  bool link_up = true;
  PdInFrame last_pd_in{};
  uint64_t cycles = 0;
  int64_t time_ns = 0;     // sum of the master cycles run
  int64_t cycle_ns = 0;    // the master cycle now
  int startup_left = 0;    // master cycles of STARTUP / PREOPERATE still to run after a power-on
  // A hand turning the flange (turn_flange): from start_rad by total_rad over n cycles.
  double turn_start_rad = 0, turn_total_rad = 0;
  uint64_t turn_cycles = 0, turn_done = 0;
  bool turning = false;
  double direction = 1.0;
  TraceRow last_row; // the row of the last cycle, whether kept, streamed or neither
  std::vector<MoveRecord> moves;
  int64_t ticked_counts = 0; // encoder reading the device saw last
  int64_t device_epoch_ns = 0; // run time of the device's last power-on
  double max_tracking_error_deg = 0; // over the run, every control step
  bool pending_in_list = false; // moves.back() is the device's open or held record
};

struct TwinSnapshot {
  DeviceSnapshot device;
  PlantSnapshot plant;
  TwinRunState run;
  std::size_t trace_rows = 0; // rows the kept trace held (A-TWIN-36: restore cuts the trace back to them)
};

} // namespace sreh
