// A motion parameter set as raw wire values (manual 6.2, index 64..71) and
// read back exactly as the device reads it (ParameterStore::motion_set), so
// that the planner sees the same numbers the firmware does.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "device_logic/parameter_store.hpp"
#include "device_logic/parameter_table.hpp"
#include "device_logic/units.hpp"
#include "sizing/sizing.hpp"

namespace sreh::sizing {
namespace {

int64_t raw_of(double display, double scale, int64_t lo, int64_t hi) {
  return std::clamp(static_cast<int64_t>(std::llround(display / scale)), lo, hi);
}

// A-SIZE-4: settling timeout when none is given: the factory 100 ms (raw
// 1000) for the factory waiting time 25 ms, i.e. the wait plus 75 ms.
double default_timeout_ms(double wait_ms) { return std::clamp(wait_ms + 75.0, 100.0, 5000.0); }

// Index 85 (manual 6.2): the factory window is 18..30 V; a supply outside it
// needs the window widened or the device reports 114.4 (A-SIZE-2).
constexpr double kFactoryMinVoltage_V = 18.0;
constexpr double kFactoryMaxVoltage_V = 30.0;

} // namespace

double voltage_speed_limit_dps(double voltage_V) { return std::min(kMaxSpeed_dps, kMaxSpeed_dps * voltage_V / 24.0); }

ParameterSetValues make_parameter_set(const SizingRequest& rq, const MotionSetting& s, double load_gcm2) {
  const auto index = static_cast<uint16_t>(64 + rq.parameter_set);
  ParameterSetValues v;
  v.set = rq.parameter_set;
  v.voltage_V = rq.voltage_V;
  const double tol_scale = 360.0 / static_cast<double>(kInternalCountsPerRev);
  const int64_t speed = raw_of(s.speed_dps, 0.1, 1, 43000);
  const int64_t accel = raw_of(s.accel_pct, 0.1, 1, 1000);
  const int64_t jerk = raw_of(s.jerk_pct, 0.1, 1, 1000);
  const int64_t load = raw_of(load_gcm2, 1.0, 0, 15000);
  const int64_t tol = raw_of(rq.tolerance_deg, tol_scale, 0, 65535);
  const int64_t wait = raw_of(rq.wait_ms, 0.1, 0, 50000);
  const int64_t timeout = raw_of(rq.timeout_ms.value_or(default_timeout_ms(rq.wait_ms)), 0.1, 0, 50000);

  // Read back through the device's own store: same scaling, same rounding.
  ParameterStore store;
  const int64_t raws[8] = {speed, accel, jerk, load, tol, wait, timeout, 1};
  for (uint8_t sub = 1; sub <= 8; ++sub) {
    const ParameterEntry* row = find_parameter(index, sub);
    const IsduResult r = store.write(index, sub, encode_number(row->type, raws[sub - 1]));
    if (!r.ok()) {
      throw std::logic_error(fmt::format("sizing: index {}.{} value {} refused (0x{:04X})", index, sub, raws[sub - 1], r.error));
    }
  }
  const MotionParameterSet m = store.motion_set(rq.parameter_set);
  v.setting = MotionSetting{m.speed_dps, m.accel_pct, m.jerk_pct};
  v.tidy = MotionSetting{static_cast<double>(speed) / 10.0, static_cast<double>(accel) / 10.0,
                         static_cast<double>(jerk) / 10.0};
  v.load_gcm2 = m.load_gcm2;
  v.tolerance_deg = m.tolerance_deg;
  v.wait_ms = m.wait_ms;
  v.timeout_ms = m.settling_timeout_ms;

  v.writes = {
      {index, 1, speed, fmt::format("speed {:.1f} deg/s", m.speed_dps)},
      {index, 2, accel, fmt::format("acceleration {:.1f} % of alpha100%", m.accel_pct)},
      {index, 3, jerk, fmt::format("jerk {:.1f} %", m.jerk_pct)},
      {index, 4, load, fmt::format("load {:.0f} g cm^2", m.load_gcm2)},
      {index, 5, tol, fmt::format("position tolerance {:.4f} deg", m.tolerance_deg)},
      {index, 6, wait, fmt::format("waiting time {:.1f} ms", m.wait_ms)},
      {index, 7, timeout, fmt::format("settling timeout {:.1f} ms", m.settling_timeout_ms)},
      {index, 8, 1, "settling timeout active"},
  };
  if (rq.voltage_V < kFactoryMinVoltage_V) {
    v.writes.push_back({85, 1, 16000, "motor voltage window minimum 16.0 V (supply below the factory 18 V)"});
  }
  if (rq.voltage_V > kFactoryMaxVoltage_V) {
    v.writes.push_back({85, 2, 32000, "motor voltage window maximum 32.0 V (supply above the factory 30 V)"});
  }
  return v;
}

} // namespace sreh::sizing
