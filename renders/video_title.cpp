#include "renders/video_title.hpp"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

namespace sreh {

TitleCard make_title_card(const TitleFacts& f) {
  TitleCard card;
  card.heading = f.scenario_name.empty() ? std::filesystem::path(f.scenario_file).stem().string() : f.scenario_name;
  if (!f.scenario_file.empty()) card.lines.emplace_back("scenario", std::filesystem::path(f.scenario_file).filename().string());
  card.lines.emplace_back("load", f.load);
  card.lines.emplace_back("load inertia", fmt::format("{:.1f} g cm^2 about the axis", std::max(0.0, f.load_inertia_gcm2)));
  if (f.sets.empty()) card.lines.emplace_back("parameter sets", "no move");
  for (const auto& [n, set] : f.sets) {
    // Manual 3.5.3-3.5.5: speed in deg/s, acceleration and jerk in % of the maximum.
    card.lines.emplace_back(fmt::format("set {}", n), fmt::format("{:g} deg/s, accel {:g} %, jerk {:g} %", set.speed_dps,
                                                                  set.accel_pct, set.jerk_pct));
  }
  card.lines.emplace_back("mounting", f.mounting_tilt_deg == 0 ? std::string("vertical axis")
                                                               : fmt::format("axis tilted {:g} deg", f.mounting_tilt_deg));
  card.lines.emplace_back("supply", fmt::format("{:g} V", f.supply_V));
  if (!f.time_scale.empty()) card.lines.emplace_back("video", f.time_scale);
  return card;
}

} // namespace sreh
