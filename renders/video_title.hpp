// The title card of a run's video (issue 29): what a viewer needs before the
// first move -- the scenario, the load and its inertia, the parameter sets
// the moves used with their speed and acceleration, mounting and supply.
// Plain facts in, the card's lines out; the CLI gathers the facts as the run
// goes (docs/interfaces.md "Video").
#pragma once
#include <map>
#include <string>

#include "device_logic/parameter_store.hpp"
#include "renders/offscreen.hpp"

namespace sreh {

struct TitleFacts {
  std::string scenario_name;
  std::string scenario_file;     // shown by its file name only
  std::string load;              // load_title() (renders/run_media.hpp): the load's own name
  double load_inertia_gcm2 = 0;  // about the axis, as the plant computes it
  double mounting_tilt_deg = 0;  // 0: vertical axis
  double supply_V = 24.0;
  std::map<int, MotionParameterSet> sets; // every set a move latched, as it was then
  std::string time_scale;        // how the video plays the run (TimeMap::describe)
};

TitleCard make_title_card(const TitleFacts& facts);

} // namespace sreh
