// A motion parameter set as raw wire values (manual 6.2, index 64..71) and
// read back exactly as the device reads it (ParameterStore::motion_set), so
// that the planner sees the same numbers the firmware does.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "device_logic/parameter_ids.hpp"
#include "device_logic/parameter_store.hpp"
#include "device_logic/parameter_table.hpp"
#include "device_logic/units.hpp"
#include "sizing/sizing.hpp"

namespace sreh::sizing {
namespace {

// A-SIZE-4: settling timeout when none is given: the factory 100 ms (raw
// 1000) for the factory waiting time 25 ms, i.e. the wait plus 75 ms, within
// the row's range.
double default_timeout_ms(double wait_ms) {
  const ParamId timeout = param::MotionSet(0).settling_timeout;
  return std::clamp(wait_ms + 75.0, display_default(timeout), display_max(timeout));
}

} // namespace

double min_voltage_V() { return display_min(param::kMotorVoltageMin); }
double max_voltage_V() { return display_max(param::kMotorVoltageMax); }
double max_speed_dps() { return display_max(param::MotionSet(0).speed); }

double voltage_speed_limit_dps(double voltage_V) { return std::min(max_speed_dps(), max_speed_dps() * voltage_V / 24.0); }

ParameterSetValues make_parameter_set(const SizingRequest& rq, const MotionSetting& s, double load_gcm2) {
  const param::MotionSet ids{rq.parameter_set};
  ParameterSetValues v;
  v.set = rq.parameter_set;
  v.voltage_V = rq.world.supply.voltage_V;
  // Raw values nearest to the request, within the table's ranges (manual 6.2).
  const int64_t speed = display_to_raw(ids.speed, s.speed_dps);
  const int64_t accel = display_to_raw(ids.acceleration, s.accel_pct);
  const int64_t jerk = display_to_raw(ids.jerk, s.jerk_pct);
  const int64_t load = display_to_raw(ids.load, load_gcm2);
  const int64_t tol = display_to_raw(ids.tolerance, rq.settling.tolerance_deg);
  const int64_t wait = display_to_raw(ids.waiting_time, rq.settling.wait_ms);
  const int64_t timeout = display_to_raw(ids.settling_timeout, rq.settling.timeout_ms.value_or(default_timeout_ms(rq.settling.wait_ms)));

  // Read back through the device's own store: same scaling, same rounding.
  ParameterStore store;
  const std::pair<ParamId, int64_t> raws[8] = {{ids.speed, speed},         {ids.acceleration, accel},
                                               {ids.jerk, jerk},           {ids.load, load},
                                               {ids.tolerance, tol},       {ids.waiting_time, wait},
                                               {ids.settling_timeout, timeout}, {ids.settling_timeout_active, 1}};
  for (const auto& [id, raw] : raws) {
    const IsduResult r = store.write(id.index, id.subindex, encode_number(parameter_row(id).type, raw));
    if (!r.ok()) {
      throw std::logic_error(fmt::format("sizing: index {}.{} value {} refused (0x{:04X})", id.index, id.subindex, raw, r.error));
    }
  }
  const MotionParameterSet m = store.motion_set(rq.parameter_set);
  v.setting = MotionSetting{m.speed_dps, m.accel_pct, m.jerk_pct};
  v.tidy = MotionSetting{raw_to_display(ids.speed, speed), raw_to_display(ids.acceleration, accel),
                         raw_to_display(ids.jerk, jerk)};
  v.load_gcm2 = m.load_gcm2;
  v.tolerance_deg = m.tolerance_deg;
  v.wait_ms = m.wait_ms;
  v.timeout_ms = m.settling_timeout_ms;

  v.writes = {
      {ids.speed.index, ids.speed.subindex, speed, fmt::format("speed {:.1f} deg/s", m.speed_dps)},
      {ids.acceleration.index, ids.acceleration.subindex, accel,
       fmt::format("acceleration {:.1f} % of alpha100%", m.accel_pct)},
      {ids.jerk.index, ids.jerk.subindex, jerk, fmt::format("jerk {:.1f} %", m.jerk_pct)},
      {ids.load.index, ids.load.subindex, load, fmt::format("load {:.0f} g cm^2", m.load_gcm2)},
      {ids.tolerance.index, ids.tolerance.subindex, tol, fmt::format("position tolerance {:.4f} deg", m.tolerance_deg)},
      {ids.waiting_time.index, ids.waiting_time.subindex, wait, fmt::format("waiting time {:.1f} ms", m.wait_ms)},
      {ids.settling_timeout.index, ids.settling_timeout.subindex, timeout,
       fmt::format("settling timeout {:.1f} ms", m.settling_timeout_ms)},
      {ids.settling_timeout_active.index, ids.settling_timeout_active.subindex, 1, "settling timeout active"},
  };
  // The widest window the table allows (manual 6.2, index 85): a supply
  // outside the factory window (the rows' defaults, 18..30 V) needs it
  // widened or the device reports 114.4 (A-SIZE-2).
  const ParamId vmin = param::kMotorVoltageMin, vmax = param::kMotorVoltageMax;
  if (rq.world.supply.voltage_V < display_default(vmin)) {
    v.writes.push_back({vmin.index, vmin.subindex, parameter_row(vmin).min,
                        fmt::format("motor voltage window minimum {:.1f} V (supply below the factory 18 V)", display_min(vmin))});
  }
  if (rq.world.supply.voltage_V > display_default(vmax)) {
    v.writes.push_back({vmax.index, vmax.subindex, parameter_row(vmax).max,
                        fmt::format("motor voltage window maximum {:.1f} V (supply above the factory 30 V)", display_max(vmax))});
  }
  return v;
}

} // namespace sreh::sizing
