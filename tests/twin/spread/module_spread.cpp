#include "tests/twin/spread/module_spread.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "device_logic/units.hpp"
#include "twin/twin.hpp"

namespace sreh::test {
namespace {

bool write_u16(Twin& twin, uint16_t index, uint8_t sub, uint16_t value) {
  const uint8_t bytes[2] = {static_cast<uint8_t>(value >> 8), static_cast<uint8_t>(value & 0xFF)};
  return twin.isdu_write(index, sub, bytes).ok();
}

// Runs master cycles until `done` or `max_s`; false if an error came first.
template <class Done>
bool run_until(Twin& twin, double max_s, Done done) {
  const int cycles = static_cast<int>(std::lround(max_s / twin.master_cycle_s()));
  for (int i = 0; i < cycles; ++i) {
    twin.run_cycle();
    if (twin.pd_in().error) return false;
    if (done(twin.pd_in())) return true;
  }
  return false;
}

// Skips `settle_s`, then samples the commanded torque and the position
// every master cycle for `measure_s`.
HoldFigures hold(Twin& twin, double settle_s, double measure_s) {
  run_until(twin, settle_s, [](const ProcessDataIn&) { return false; });
  double t_lo = 1e9, t_hi = -1e9, p_lo = 1e9, p_hi = -1e9;
  const int cycles = static_cast<int>(std::lround(measure_s / twin.master_cycle_s()));
  for (int i = 0; i < cycles && !twin.pd_in().error; ++i) {
    twin.run_cycle();
    const Telemetry t = twin.telemetry();
    t_lo = std::min(t_lo, t.torque_Nm), t_hi = std::max(t_hi, t.torque_Nm);
    p_lo = std::min(p_lo, t.position_deg), p_hi = std::max(p_hi, t.position_deg);
  }
  if (t_hi < t_lo) return {}; // an error came first: no samples (the run's error code tells)
  return {t_hi - t_lo, p_hi - p_lo};
}

} // namespace

ModuleModel module_with(const std::vector<std::pair<std::string, double>>& values) {
  ModelCard card = default_model_card();
  for (const auto& entry : values) { // not a structured binding: clang 14 cannot capture one
    const std::string& name = entry.first;
    auto it = std::find_if(card.constants.begin(), card.constants.end(),
                           [&](const ModelConstant& c) { return c.name == name; });
    if (it == card.constants.end()) throw std::invalid_argument("no constant " + name);
    it->value = entry.second;
  }
  return card.module_model();
}

const char* mounting_name(Mounting m) {
  switch (m) {
    case Mounting::VerticalEmpty: return "vertical, no load";
    case Mounting::VerticalRatedDisk: return "vertical, 15000 g cm^2 disk";
    case Mounting::HorizontalRatedArm: return "horizontal, rated arm 0.15 kg at 99.9 mm";
  }
  return "?";
}

SpreadRun run_module(const ModuleModel& module, Mounting mounting) {
  TwinConfig c;
  c.module = module;
  c.record_trace = false;
  c.visual_detail = false;
  uint16_t load_gcm2 = 0;
  uint16_t accel_permille = 1000;
  if (mounting == Mounting::VerticalRatedDisk) {
    c.load = InertiaLoad{15000};
    load_gcm2 = 15000;
  } else if (mounting == Mounting::HorizontalRatedArm) {
    c.load = ArmLoad{0.15, 0.0999, 0.0}; // 14970 g cm^2, m g r = 0.147 N m (scenario gravity_arm_horizontal_rated_50pct)
    c.mounting_tilt_deg = 90;
    load_gcm2 = 14970;
    accel_permille = 500;
  }
  Twin twin(c);
  SpreadRun out;
  if (!write_u16(twin, 64, 4, load_gcm2) || !write_u16(twin, 65, 4, load_gcm2) || !write_u16(twin, 65, 1, 30000) ||
      !write_u16(twin, 65, 2, accel_permille)) {
    throw std::runtime_error("spread run: a parameter write was refused");
  }
  ProcessDataOut pd;
  pd.motor_on = true;
  pd.parameter_set = 1;
  twin.set_pd_out(pd);
  out.ready = run_until(twin, 0.02, [](const ProcessDataIn& in) { return in.ready; });
  if (!out.ready) {
    out.error_code = twin.pd_in().error_code;
    return out;
  }
  out.after_motor_on = hold(twin, 0.1, 0.2);
  for (double target : {90.0, -90.0, 0.0}) {
    if (twin.pd_in().error) break;
    pd.target_raw = static_cast<int32_t>(deg_to_wire_counts(target));
    pd.move = true;
    twin.set_pd_out(pd);
    if (!run_until(twin, 1.0, [](const ProcessDataIn& in) { return in.done; })) break;
    ++out.moves_completed;
    if (!twin.moves().empty()) out.max_settling_s = std::max(out.max_settling_s, twin.moves().back().settling_s.value_or(0.0));
    pd.move = false;
    twin.set_pd_out(pd);
    twin.run_cycle();
  }
  if (!twin.pd_in().error) out.after_moves = hold(twin, 0.1, 0.2);
  out.error_code = twin.pd_in().error_code;
  return out;
}

std::vector<std::vector<std::pair<std::string, double>>> latin_hypercube(int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  // Uniform in [0, 1) from the engine's bits (the engine is specified by
  // the standard; the distributions are not, so they are not used).
  auto uniform = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  std::vector<std::vector<std::pair<std::string, double>>> samples(static_cast<std::size_t>(n));
  for (const ModelConstant& c : default_model_card().constants) {
    if (!(c.range_hi > c.range_lo)) continue;
    std::vector<int> strata(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) strata[static_cast<std::size_t>(i)] = i;
    for (int i = n - 1; i > 0; --i) { // Fisher-Yates with the engine's bits
      const int j = static_cast<int>(rng() % static_cast<uint64_t>(i + 1));
      std::swap(strata[static_cast<std::size_t>(i)], strata[static_cast<std::size_t>(j)]);
    }
    for (int i = 0; i < n; ++i) {
      double v = c.range_lo + (strata[static_cast<std::size_t>(i)] + uniform()) / n * (c.range_hi - c.range_lo);
      if (model_constant_is_whole(c.name)) v = std::clamp(std::round(v), c.range_lo, c.range_hi);
      samples[static_cast<std::size_t>(i)].emplace_back(c.name, v);
    }
  }
  return samples;
}

} // namespace sreh::test
