// A studio project (issue 37): the load as parts, the single move and the
// options, as the page edits them (a JSON "state") and as a file (YAML).
// The file is a load file (scenarios/load_file.hpp: `name:`, `load:`,
// `mounting:`) plus a `studio:` section with the move and the options, so
// `sreh-twin size --load PROJECT.yaml` reads its load and mounting and
// `sreh-twin studio PROJECT.yaml` reopens all of it (docs/studio.md).
//
// State JSON (every key optional but `parts`):
//   {"name": "...", "parts": [{"name": "...", "shape": "disk", "mass_kg": 0.2,
//     "radius_m": 0.04, "thickness_m": 0.01, "at_m": [x, y, z], "rpy_deg": [r, p, y]}],
//    "mounting_tilt_deg": 0, "angle_deg": 90, "dwell_s": 0, "tolerance_deg": 0.1,
//    "target": "positioning" | "cycle" | "none", "target_ms": 300,
//    "voltage_V": 24, "ambient_C": 25,
//    "set": null | {"speed_dps": ..., "accel_pct": ..., "jerk_pct": ...},
//    "mode": "single" | "cycle", "uncertainty": false,
//    "segments": [{"kind": "move", "deg": 90, "relative": false}, {"kind": "dwell", "s": 0.2},
//                 {"kind": "grip"}, {"kind": "release"}]}
//   A part's "payload": true puts it on the flange only from a grip to a
//   release (cycles); a single move sizes with every part.
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sizing/size_options.hpp"

namespace sreh::studio {

using Json = nlohmann::json;

// A state or project the studio cannot use: one message naming what and
// where (the CLI's exit 2, the page's error line).
class ProjectError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The part shapes the builder offers (the load file's simple shapes,
// scenarios/README.md "load") and the keys of each, mass first.
struct ShapeKeys {
  const char* shape;
  std::vector<const char*> keys;
};
const std::vector<ShapeKeys>& part_shapes();

// The state with every default filled in and every value checked for
// type (ranges are the sizing's and the load parser's to check).
Json normalised_state(const Json& state);

// The project file's text for a state (deterministic): a single move's is
// a load file (`size --load` reads it), a cycle's a cycle file (`size
// --cycle` reads it), each with the `studio:` section.
std::string project_yaml(const Json& state);
// The load file of the state: name, every part (payload too), mounting.
// With `mass_scale` every part's mass is multiplied (figures of a load over the limit).
std::string load_yaml(const Json& state, double mass_scale = 1.0);
// `parts:` of a load file, each line indented by `indent`.
std::string parts_yaml(const Json& parts, const std::string& indent, double mass_scale = 1.0);
// The cycle file of a cycle state (cycle_project.cpp): the load without the
// payload parts, mounting, supply, ambient, tolerance and the segments, a
// grip loading every part, a release the load without the payload.
std::string cycle_file_yaml(const Json& state);

// The state a project file (or a plain load file of simple parts) holds.
// Throws ProjectError "FILE:LINE:COL: ..." for a file the studio cannot read.
Json state_from_project_text(const std::string& text, const std::string& file);
Json state_from_project_file(const std::string& path);

// What `sreh-twin size` would be given for the state (its load as the
// project file): the same SizeOptions, so the studio's answer is the
// command's. `load_file` names the project file in the command line.
sizing::SizeOptions size_options(const Json& state);
// "sreh-twin size --load FILE --angle-deg 90 ...": the command giving the same answer.
std::string size_command_line(const Json& state, const std::string& load_file);

} // namespace sreh::studio
