// The twin: the device logic coupled to the MuJoCo plant on integer clocks
// (architecture.md "Time"): physics and control every physics step, process
// data every IO-Link cycle. Deterministic: same inputs, same trace.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "device_logic/device.hpp"
#include "twin/specs.hpp"
#include "twin/trace.hpp"

struct mjModel_;
struct mjData_;

namespace sreh {

// twin/twin_snapshot.hpp: include it where a snapshot is taken or looked
// into; naming it here keeps the device's insides out of every user of Twin.
struct TwinSnapshot;

// The twin's configuration: the world (twin/specs.hpp, shared with
// PlantConfig) plus the IO-Link cycle, the memory and the trace handling.
struct TwinConfig : WorldSpec {
  double cycle_s = 0.002;        // IO-Link master cycle at the start; an integer multiple of physics_dt_s,
                                 // 0.002 .. 0.1328 s (manual 1, IO-Link MasterCycleTime; A-LINK-2)
  std::optional<std::vector<uint8_t>> nvm_image; // saved memory; factory-new otherwise
  bool record_trace = true;       // keep every row in memory: trace()
  // When set, every row goes here instead (streaming; trace() stays empty),
  // so memory stays flat however long the run (issue 12).
  std::function<void(const TraceRow&)> trace_sink;
  // When set, every finished move record goes here instead, in order; moves()
  // keeps only the record still open or held (memory flat with run length).
  std::function<void(const MoveRecord&)> move_sink;
  // The module's textures at full size, for renderers; false for a twin
  // never drawn (sizing): faster to build (PlantConfig::visual_detail).
  bool visual_detail = true;
};

class Plant; // twin/plant.hpp

class Twin {
 public:
  explicit Twin(const TwinConfig& config); // throws std::invalid_argument on a bad load / config
  ~Twin();
  Twin(const Twin&) = delete;
  Twin& operator=(const Twin&) = delete;

  // PLC side, applied at the next IO-Link cycle boundary.
  void set_pd_out(const ProcessDataOut& out);
  const ProcessDataOut& pd_out() const;
  void set_outputs_valid(bool valid);   // manual 5
  void set_link_up(bool up);            // cycles stop while down (manual 5)
  ProcessDataIn pd_in() const;          // last frame the master received
  IsduResult isdu_read(uint16_t index, uint8_t subindex);
  IsduResult isdu_write(uint16_t index, uint8_t subindex, std::span<const uint8_t> data);

  // World side.
  void set_external_torque(double torque_Nm);
  void set_supply_voltage(double volts);
  // The flange held by something rigid (a clamp, a jammed load): a MuJoCo
  // constraint holds it at its angle whatever torque acts (not a flag the
  // device sees); released with false (A-TWIN-15).
  void set_flange_blocked(bool blocked);
  bool flange_blocked() const;
  void set_ambient_C(double celsius);   // room temperature from now on (thermal model follows)
  // Another load on the flange from now on (a gripper picks or releases a
  // part; Plant::set_load, A-TWIN-33). The device is not told: its
  // configured load is whatever index 64+n.4 of the set says. Throws
  // std::invalid_argument for a load the module cannot carry (no change).
  void set_load(const LoadSpec& load);
  // The master's cycle time from the next cycle on (a rig reconfiguring its
  // master): 0.002 .. 0.1328 s and an integer multiple of physics_dt_s, else
  // std::invalid_argument and nothing changes. The master announces it to the
  // device (MasterCycleTime), whose link watchdog follows (A-LINK-1).
  void set_master_cycle_s(double cycle_s);
  double master_cycle_s() const;

  // Supply interruption (manual 4.1, 5, 9). power_cycle(): off and on at once.
  // power_off_for(): off for off_s (whole master cycles, the world keeps
  // running), while a hand turns the flange by turn_deg (physical frame:
  // clockwise seen from above positive, as hard stops; evenly over the off
  // time), then on. After every power-on the master takes the device through
  // STARTUP and PREOPERATE (one cycle each) to OPERATE (A-LINK-3), so the
  // module has started up within 3 master cycles (< 0.4 s, well under 1 s).
  // Non-volatile memory is kept.
  void power_cycle();
  void power_off_for(double off_s, double turn_deg = 0.0);
  void power_off();                     // the primitives: supply off ...
  void power_on();                      // ... and on again (start-up follows)
  bool powered() const;
  // Manual 8: another module of the type mounted in this one's place (serve's
  // replace_device fault): a factory-new device (memory, counters) powered on
  // at the flange's angle; the world stays.
  void replace_device();
  // A hand turns the flange by turn_deg (physical frame) evenly over the next
  // over_s (whole master cycles; 0: at once). Meant for an unpowered module.
  void turn_flange(double turn_deg, double over_s);

  // Manual 9: transfer a firmware image to the device in boot mode, in ISDU
  // chunks over simulated time (twin/firmware_transfer.hpp, A-FW-4, A-FW-5).
  // Returns 0 or the ISDU error code of the first request that failed.
  uint16_t firmware_update(std::span<const uint8_t> image);

  // Advance one IO-Link cycle (exchange, then cycle_s / physics_dt_s steps).
  void run_cycle();
  uint64_t cycles() const;
  double time_s() const;                // sum of the master cycles run (integer nanoseconds)
  IoLinkLedMode iolink_led() const;     // the IO-Link status LED now (manual 1)

  Telemetry telemetry() const;
  const std::vector<TraceRow>& trace() const;
  // The row of the last cycle (before run_cycle(): a default row), whether
  // the trace is kept, streamed or neither: what an observer such as the
  // video overlay shows.
  const TraceRow& last_row() const;
  // One record per accepted Move, from the device (issue 13); the last may
  // still be open (or its target held) while the run goes on. With
  // TwinConfig::move_sink only that open or held record.
  const std::vector<MoveRecord>& moves() const;
  // The largest |setpoint - encoder| of any control step so far (motor on).
  double max_tracking_error_deg() const;
  double load_inertia_gcm2() const;     // actual load about the axis, as MuJoCo computes it
  const Device& device() const;
  const Plant& plant() const;
  std::vector<uint8_t> save_nvm() const;

  // The whole running twin as a value (twin/twin_snapshot.hpp): device,
  // MuJoCo state, drive, supply, thermal, clocks, link, load. restore()
  // puts this twin (or another made with the same config) back exactly
  // there; it then continues bit for bit as after the snapshot. A load
  // changed since (set_load) is changed back (A-TWIN-34); a snapshot of a
  // different world (physics step, hard stops, mounting, module model)
  // throws std::invalid_argument and nothing changes (A-TWIN-35); the kept
  // trace is cut back to the snapshot's rows (A-TWIN-36).
  TwinSnapshot snapshot() const;
  void restore(const TwinSnapshot& snapshot);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace sreh
