// Replaying a master log through the twin (issue 26): the logged process
// data output goes in cycle by cycle exactly as the master sent it; what the
// twin's encoder then reads is compared with the logged position. A log
// replayed with the model that recorded it gives the logged frames back bit
// for bit (calibration_test checks it), so every residual is the model's.
#pragma once
#include <vector>

#include "calibration/master_log.hpp"
#include "scenarios/scenario.hpp"
#include "twin/twin.hpp"

namespace sreh {

// What the log does not carry: the world (load, mounting, supply, physics
// step) and the acyclic writes made before the log starts (the parameter
// sets): a setup scenario's `device.isdu` writes, or, without one, the
// configured load of every set (64..71.4) written from the load (A-CAL-2).
struct ReplaySetup {
  TwinConfig config;                       // load, mounting, supply, physics step; cycle_s from the log
  std::vector<IsduWriteStep> startup_writes;
  bool configure_load = true;
  // The load the module carries is config.load (the stated one) scaled by
  // this (the fit of the load, calibration/load_scale.hpp, A-CAL-14); the
  // sets stay configured for the stated load, as the PLC wrote them.
  double load_scale = 1.0;
};

// The setup a log was recorded with. `scenario` (optional, `calibrate
// --setup`) supplies its world and `device.isdu` writes; `load` replaces its
// load. The master cycle is the log's row spacing, which must be constant:
// CalibrationInputError naming file:line otherwise.
ReplaySetup replay_setup(const MasterLog& log, const LoadSpec& load, const Scenario* scenario);

// What the model predicts for each logged row.
struct ReplayTrack {
  // What the row's pd_in frame was made from: the encoder and the sensor as
  // the previous cycle left them, process-data degrees (A-CAL-1).
  std::vector<double> position_deg;
  std::vector<double> temperature_C;
  std::vector<PdInFrame> pd_in;      // the frames the twin answered with
};

ReplayTrack replay(const ReplaySetup& setup, const ModuleModel& module, const MasterLog& log);

// The master log `scenario` gives on a module with `module`'s constants, in
// memory as `run --master-log` writes it: one row per cycle, a polled
// temperature (index 112, manual 6.4) on the row after the read.
MasterLog record_master_log(Scenario scenario, const ModuleModel& module);

} // namespace sreh
