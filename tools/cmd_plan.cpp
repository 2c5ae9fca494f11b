// `sreh-twin plan`: the S-curve the device plans for one move and motion
// parameter set (manual 3.5.3-3.5.6), as text or one JSON object
// (interfaces.md). Exit 0, or 2 for a value outside the manual's ranges.
#include <array>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "device_logic/parameter_ids.hpp"
#include "device_logic/planner.hpp"
#include "device_logic/units.hpp"
#include "tools/command.hpp"

namespace sreh::tools {
namespace {

// Parameter set 1's rows: ranges and factory defaults come from the table (manual 6.2).
const param::MotionSet kSet{1};

struct PlanArgs {
  double distance_deg = 0;
  double speed_dps = display_default(kSet.speed);
  double accel_pct = display_default(kSet.acceleration);
  double jerk_pct = display_default(kSet.jerk);
  double load_gcm2 = display_default(kSet.load);
  bool json = false;
};

void check_range(const char* option, double value, ParamId id) {
  const double lo = display_min(id), hi = display_max(id);
  if (!std::isfinite(value) || value < lo || value > hi) {
    throw InputError(fmt::format("{} {} is outside the manual's range {} .. {} {} (manual {}, index 64..71)", option,
                                 value, lo, hi, parameter_row(id).display_unit, parameter_row(id).section));
  }
}

std::string range_help(std::string_view what, ParamId id, std::string_view section) {
  return fmt::format("{}, {} .. {} {} (manual {})", what, display_min(id), display_max(id),
                     parameter_row(id).display_unit, section);
}

int plan_command(const PlanArgs& a) {
  check_range("--speed-dps", a.speed_dps, kSet.speed);
  check_range("--accel-pct", a.accel_pct, kSet.acceleration);
  check_range("--jerk-pct", a.jerk_pct, kSet.jerk);
  check_range("--load-gcm2", a.load_gcm2, kSet.load);
  // The target is an int32 of 2^16 counts per revolution (manual 2.5).
  const double max_distance_deg = wire_counts_to_deg(int64_t{1} << 31);
  if (!std::isfinite(a.distance_deg) || std::abs(a.distance_deg) > max_distance_deg) {
    throw InputError(fmt::format("--distance-deg {} is outside +-{} deg (int32 target, manual 2.5)",
                                 a.distance_deg, max_distance_deg));
  }

  const MotionLimits l = limits_from_parameter_set(a.speed_dps, a.accel_pct, a.jerk_pct, a.load_gcm2);
  const Profile p = Profile::rest_to_rest(deg_to_rad(a.distance_deg), l);
  const std::array<double, 7>& ph = p.phase_durations_s();
  const double amax_dps2 = rad_to_deg(l.a_max_rad_s2);
  const double jmax_dps3 = rad_to_deg(l.j_max_rad_s3);
  const double peak_speed_dps = std::abs(rad_to_deg(p.peak_velocity_rad_s()));
  const double peak_accel_dps2 = rad_to_deg(l.j_max_rad_s3 * ph[0]);
  const bool speed_reached = ph[3] > 0.0;
  const bool accel_reached = ph[1] > 0.0 || (ph[0] > 0.0 && peak_accel_dps2 >= amax_dps2 * (1 - 1e-12));

  if (a.json) {
    nlohmann::json j;
    j["distance_deg"] = a.distance_deg;
    j["speed_dps"] = a.speed_dps;
    j["accel_pct"] = a.accel_pct;
    j["jerk_pct"] = a.jerk_pct;
    j["load_gcm2"] = a.load_gcm2;
    j["travel_s"] = p.duration_s();
    j["phases_s"] = ph;
    j["amax_dps2"] = amax_dps2;
    j["jmax_dps3"] = jmax_dps3;
    j["peak_speed_dps"] = peak_speed_dps;
    j["peak_accel_dps2"] = peak_accel_dps2;
    j["speed_reached"] = speed_reached;
    j["accel_reached"] = accel_reached;
    std::cout << j.dump() << "\n";
    return 0;
  }
  static constexpr std::array<const char*, 7> kNames = {"jerk up",   "const accel", "jerk down", "cruise",
                                                        "jerk down", "const decel", "jerk up"};
  std::cout << fmt::format("S-curve for {} deg: {} deg/s, accel {} %, jerk {} %, load {} g cm^2\n", a.distance_deg,
                           a.speed_dps, a.accel_pct, a.jerk_pct, a.load_gcm2);
  for (std::size_t i = 0; i < ph.size(); ++i) {
    std::cout << fmt::format("  phase {} {:<12} {:12.6f} s\n", i + 1, kNames[i], ph[i]);
  }
  std::cout << fmt::format("travel time   {:.6f} s\n", p.duration_s());
  std::cout << fmt::format("amax          {:.6g} deg/s^2{}\n", amax_dps2, accel_reached ? "" : " (not reached)");
  std::cout << fmt::format("jmax          {:.6g} deg/s^3\n", jmax_dps3);
  std::cout << fmt::format("peak speed    {:.6g} deg/s{}\n", peak_speed_dps, speed_reached ? "" : " (set speed not reached)");
  return 0;
}

} // namespace

SREH_REGISTER_COMMAND(20, [](CLI::App& app, int& exit_code) {
  auto args = std::make_shared<PlanArgs>();
  CLI::App* cmd = app.add_subcommand("plan", "Show the S-curve the device plans for a move and a motion parameter set");
  cmd->add_option("--distance-deg", args->distance_deg, "Move distance in degrees (any sign)")->required();
  cmd->add_option("--speed-dps", args->speed_dps, range_help("Maximum speed", kSet.speed, "3.5.3"))->capture_default_str();
  cmd->add_option("--accel-pct", args->accel_pct, range_help("Acceleration factor", kSet.acceleration, "3.5.4"))->capture_default_str();
  cmd->add_option("--jerk-pct", args->jerk_pct, range_help("Jerk factor", kSet.jerk, "3.5.5"))->capture_default_str();
  cmd->add_option("--load-gcm2", args->load_gcm2, range_help("Configured load inertia", kSet.load, "3.5.6"))->capture_default_str();
  cmd->add_flag("--json", args->json, "Print one JSON object");
  cmd->callback([args, &exit_code] { exit_code = plan_command(*args); });
});

} // namespace sreh::tools
