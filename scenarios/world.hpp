// The world a run happens in, declared once (issue 30): scenarios
// (scenario.hpp), single-move sizing requests (sizing/sizing.hpp) and cycle
// requests (sizing/cycle.hpp) hold one `WorldSetup` as a member; one reader
// (world_parser.hpp) takes its keys from scenario and cycle files alike,
// and twin_config() is the one place it becomes the twin's configuration.
#pragma once
#include <string>

#include "scenarios/source_loc.hpp"
#include "twin/twin.hpp"

namespace sreh {

// The twin's WorldSpec (twin/specs.hpp: load, hard stops, supply, ambient
// and thermal time scale, mounting tilt, physics step, the model card with
// its overrides applied) and where the file-given parts came from.
struct WorldSetup : WorldSpec {
  SourceLoc load_loc;      // of `load:`; messages about the load cite it
  std::string model_file;  // `model: FILE` or `--model FILE`, resolved; "" none
  SourceLoc model_loc;     // of `model:` (unknown for --model)
};

// The ranges a world's numbers must lie in. One set for every file
// (A-SCN-1); a caller that asks a narrower question narrows the supply and
// the ambient (sizing: the index 85 voltage window and the module's
// operating ambient, A-SCN-32).
struct WorldRanges {
  double min_supply_V = 0.0, max_supply_V = 40.0;
  double min_ambient_C = -40.0, max_ambient_C = 100.0;
};
// A-SCN-1, A-SCN-32: the source model's ranges, alike for every caller.
inline constexpr double kMaxSourceResistance_ohm = 1000.0;
inline constexpr double kMaxBusCapacitance_F = 10.0;

// The twin's configuration for this world: every WorldSpec field as given,
// the rest (IO-Link cycle, memory image, trace handling) at its default.
TwinConfig twin_config(const WorldSpec& world);

} // namespace sreh
