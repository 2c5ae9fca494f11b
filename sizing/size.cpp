// validate(), and size(): evaluate the given set, or search (search.cpp,
// A-SIZE-10) the fastest feasible one or the gentlest one meeting a target.
#include <cmath>
#include <future>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "device_logic/parameter_ids.hpp"
#include "device_logic/units.hpp"
#include "scenarios/load_file.hpp"
#include "sizing/run_parts.hpp"
#include "sizing/sizing.hpp"
#include "sizing/twin_factory.hpp"
#include "twin/load_builder.hpp"
#include "twin/model_card.hpp"

namespace sreh::sizing {
namespace {

void check_range(const char* option, double value, double lo, double hi, const char* unit, const char* why) {
  if (!std::isfinite(value) || value < lo || value > hi) {
    throw SizingInputError(fmt::format("{} {} is outside {} .. {}{} ({})", option, value, lo, hi, unit, why));
  }
}

// A value a parameter-table row holds: its display range (manual 6.2).
void check_row(const char* option, double value, ParamId row, const char* unit, const char* why) {
  check_range(option, value, display_min(row), display_max(row), unit, why);
}


} // namespace

WorldRanges sizing_world_ranges() {
  WorldRanges r;
  r.min_supply_V = min_voltage_V();
  r.max_supply_V = max_voltage_V();
  r.min_ambient_C = 0.0; // A-SIZE-1
  r.max_ambient_C = 50.0;
  return r;
}

ModuleModel module_from_option(const std::string& model_path) {
  try {
    return load_module_model(model_path);
  } catch (const ModelCardError& e) {
    throw SizingInputError(fmt::format("--model: {}", e.what()));
  }
}

double validate(const SizingRequest& rq) {
  if (!std::isfinite(rq.angle_deg) || std::abs(rq.angle_deg) > kMaxAngle_deg) {
    throw SizingInputError(fmt::format("--angle-deg {} is outside +-{} deg (A-SIZE-1)", rq.angle_deg, kMaxAngle_deg));
  }
  if (deg_to_wire_counts(rq.angle_deg) == 0) {
    throw SizingInputError(fmt::format("--angle-deg {} is no move: below one position count (360/65536 deg, manual 2.5)",
                                       rq.angle_deg));
  }
  const WorldRanges world = sizing_world_ranges();
  check_range("--voltage-V", rq.world.supply.voltage_V, world.min_supply_V, world.max_supply_V, " V",
              "the motor voltage window index 85 can be configured to, manual 6.2");
  check_range("--dwell-s", rq.dwell_s, 0.0, kMaxDwell_s, " s", "A-SIZE-1");
  const param::MotionSet set(0); // every set has the same rows
  check_row("--tolerance-deg", rq.settling.tolerance_deg, set.tolerance, " deg", "index 64+n.5: uint16 of 2^-19 rev, manual 6.2");
  check_row("--wait-ms", rq.settling.wait_ms, set.waiting_time, " ms", "index 64+n.6, manual 6.2");
  if (rq.settling.timeout_ms) {
    check_row("--timeout-ms", *rq.settling.timeout_ms, set.settling_timeout, " ms", "index 64+n.7, manual 6.2");
  }
  check_range("--ambient-C", rq.world.thermal.ambient_C, world.min_ambient_C, world.max_ambient_C, " degC", "A-SIZE-1");
  check_range("--parameter-set", rq.parameter_set, 0, param::kMotionSets - 1, "", "index 64..71, manual 6.2");
  check_range("--cycles", rq.cycles, 1, 20, "", "A-SIZE-3");
  check_range("--thermal-margin-K", rq.thermal_margin_K, 0.0, kMaxThermalMargin_K, " K",
              "required distance below the 70 degC warning, A-SIZE-5");
  if (rq.max_positioning_ms) check_range("--max-positioning-ms", *rq.max_positioning_ms, 1.0, 600000.0, " ms", "A-SIZE-10");
  check_range("--source-resistance-ohm", rq.world.supply.source_resistance_ohm, 0.0, kMaxSourceResistance_ohm, " ohm",
              "A-SCN-32");
  check_range("--bus-capacitance-F", rq.world.supply.bus_capacitance_F, 0.0, kMaxBusCapacitance_F, " F", "A-SCN-32");
  check_range("--mounting-tilt-deg", rq.world.mounting_tilt_deg, kMinMountingTiltDeg, kMaxMountingTiltDeg,
              " deg", "0 vertical, 90 horizontal, A-TWIN-24");
  check_range("--handshake-cycles", rq.handshake_cycles, 0, 100, "", "IO-Link cycles per move, A-SIZE-16");
  if (rq.max_cycle_ms) check_range("--max-cycle-ms", *rq.max_cycle_ms, 1.0, 600000.0, " ms", "A-SIZE-10");
  if (rq.setting) {
    const char* why = "manual 6.2, index 64..71";
    check_row("--speed-dps", rq.setting->speed_dps, set.speed, " deg/s", why);
    check_row("--accel-pct", rq.setting->accel_pct, set.acceleration, " %", why);
    check_row("--jerk-pct", rq.setting->jerk_pct, set.jerk, " %", why);
  }
  if (const auto* j = std::get_if<InertiaLoad>(&rq.world.load)) {
    if (!std::isfinite(j->inertia_gcm2) || j->inertia_gcm2 < 0 || j->inertia_gcm2 > max_load_gcm2()) {
      throw SizingInputError(fmt::format(
          "--load-gcm2 {} is outside 0 .. {} g cm^2 (the module's load limit, manual 3.5.6, 6.2 index 64.4)",
          j->inertia_gcm2, max_load_gcm2()));
    }
  }
  // The load as a default twin builds it (the twin refuses > 15000 g cm^2
  // itself); from the model cache after the first time (issue 31).
  double load = 0;
  try {
    const TwinConfig cfg;
    load = kgm2_to_gcm2(built_load_inertia_kgm2(rq.world.load, cfg.hard_stops, cfg.physics_dt_s, cfg.module.mechanics));
  } catch (const std::invalid_argument& e) {
    throw SizingInputError(e.what());
  }
  if (load > max_load_gcm2() + 1e-6) {
    throw SizingInputError(fmt::format("load inertia {:.1f} g cm^2 is above the module's limit of {} g cm^2 "
                                       "(manual 3.5.6, 6.2 index 64.4)", load, max_load_gcm2()));
  }
  return std::max(0.0, load); // no load reads -1e-12
}

SizingResult size(const SizingRequest& rq, const SetJudge& judge) {
  const double load_gcm2 = validate(rq);
  SizingResult result;
  if (rq.setting) {
    result.evaluation = evaluate(rq, make_parameter_set(rq, *rq.setting, load_gcm2), rq.keep_trace);
    result.simulations = 1;
    result.feasible = result.evaluation.feasible;
    result.binding_limit = result.evaluation.binding_limit;
    result.best_positioning_s = result.evaluation.positioning_s;
    result.best_cycle_s = result.evaluation.cycle_s;
    return result;
  }
  // The first run's twin is built (its lean model compiled) on another
  // thread while the search plans its grid (issue 37): then it waits in the
  // pool (twin_factory.hpp).
  std::future<void> warm;
  if (rq.search_threads > 1 && !judge) {
    warm = std::async(std::launch::async, [&rq] { (void)fresh_twin(sizing_twin_config(rq.world)); });
  }
  result = (rq.max_positioning_ms || rq.max_cycle_ms) ? search_gentlest(rq, load_gcm2, judge)
                                                           : search_fastest(rq, load_gcm2, judge);
  // The search's runs keep their traces (search.cpp Runner::judged); an
  // answer without one (a judge's, a failed search's) is run again with it.
  if (rq.keep_trace && result.evaluation.trace.empty()) {
    result.evaluation = evaluate(rq, result.evaluation.set, true); // deterministic: the same run again, with its trace
    ++result.simulations;
  }
  return result;
}

} // namespace sreh::sizing
