#include "calibration/replay.hpp"

#include <cmath>

#include <fmt/format.h>

#include "calibration/load_scale.hpp"
#include "device_logic/parameter_table.hpp"
#include "scenarios/runner.hpp"

namespace sreh {
namespace {

constexpr uint16_t kFirstSetIndex = 64; // manual 6.2: motion parameter sets 64..71
constexpr uint16_t kLastSetIndex = 71;
constexpr uint8_t kLoadSubindex = 4;    // 64+n.4 configured load, g cm^2
constexpr double kTimeSlack_s = 1e-6;   // logs print t_s in microseconds

// The log's master cycle: its row spacing, a whole number of physics steps.
double master_cycle_s(const MasterLog& log, double physics_dt_s) {
  const double first_s = log.rows[1].t_s - log.rows[0].t_s;
  const double steps = std::round(first_s / physics_dt_s);
  const double cycle_s = steps * physics_dt_s;
  if (steps < 1 || std::abs(cycle_s - first_s) > kTimeSlack_s) {
    throw CalibrationInputError(fmt::format("{}:{}: rows {:g} s apart, not a whole number of {:g} s physics steps",
                                            log.path, log.rows[1].line, first_s, physics_dt_s));
  }
  for (std::size_t i = 1; i < log.rows.size(); ++i) {
    const double expected_s = log.rows[0].t_s + static_cast<double>(i) * cycle_s;
    if (std::abs(log.rows[i].t_s - expected_s) > kTimeSlack_s) {
      throw CalibrationInputError(fmt::format(
          "{}:{}: t_s {:.6f}, expected {:.6f}: the log must have one row per master cycle of {:g} s (A-CAL-1)",
          log.path, log.rows[i].line, log.rows[i].t_s, expected_s, cycle_s));
    }
  }
  return cycle_s;
}

} // namespace

ReplaySetup replay_setup(const MasterLog& log, const LoadSpec& load, const Scenario* scenario) {
  ReplaySetup s;
  if (scenario) {
    s.config = twin_config(scenario->world); // its world; replay() puts the fitted module in
    s.startup_writes = scenario->device.isdu;
    s.configure_load = false;
  }
  if (!std::holds_alternative<NoLoad>(load)) s.config.load = load;
  s.config.cycle_s = master_cycle_s(log, s.config.physics_dt_s);
  s.config.record_trace = false;
  s.config.visual_detail = false; // never drawn: the lean model, faster builds and steps (issue 31, A-TWIN-42)
  return s;
}

ReplayTrack replay(const ReplaySetup& setup, const ModuleModel& module, const MasterLog& log) {
  TwinConfig config = setup.config;
  config.module = module;
  if (setup.load_scale != 1.0) config.load = scaled_load(config.load, setup.load_scale);
  Twin twin(config);
  // Without a setup scenario: the configured load of every set from the
  // stated load, whole g cm^2 (manual 3.5.6, A-CAL-2); with one, its writes.
  if (setup.configure_load) {
    const auto load_raw = encode_number(ParamType::UInt16, std::llround(twin.load_inertia_gcm2() / setup.load_scale));
    for (uint16_t index = kFirstSetIndex; index <= kLastSetIndex; ++index) twin.isdu_write(index, kLoadSubindex, load_raw);
  }
  for (const IsduWriteStep& w : setup.startup_writes) twin.isdu_write(w.index, w.subindex, w.data);
  ReplayTrack track;
  track.position_deg.reserve(log.rows.size());
  track.temperature_C.reserve(log.rows.size());
  track.pd_in.reserve(log.rows.size());
  for (const MasterLogRow& row : log.rows) {
    // The frame the master receives in a cycle is sent at its start: it
    // carries the encoder as the previous cycle left it (A-CAL-1).
    const Telemetry before = twin.telemetry();
    track.position_deg.push_back(before.position_deg);
    track.temperature_C.push_back(before.temperature_C);
    twin.set_pd_out(decode_out(row.pd_out));
    twin.run_cycle();
    track.pd_in.push_back(twin.last_row().pd_in);
  }
  return track;
}

MasterLog record_master_log(Scenario scenario, const ModuleModel& module) {
  scenario.world.module = module;
  MasterLog log;
  log.path = "recorded.csv";
  log.has_temperature = true;
  std::optional<double> polled_C;
  RunOptions o;
  o.trace_sink = [&](const TraceRow& r) {
    MasterLogRow row;
    row.t_s = r.t_s;
    row.pd_out = r.pd_out;
    row.pd_in = r.pd_in;
    row.temperature_C = polled_C;
    polled_C.reset();
    row.line = static_cast<int>(log.rows.size()) + 2; // after the header, as the file would number it
    log.rows.push_back(row);
  };
  o.on_isdu_read = [&](uint16_t index, uint8_t subindex, const IsduResult& result) {
    if (index == 112 && subindex == 0 && result.ok() && result.data.size() == 1) polled_C = 0.5 * result.data[0]; // manual 6.4
  };
  run_scenario(scenario, o);
  return log;
}

} // namespace sreh
