// The studio's answer to a state (issue 37): the load's figures, and the
// sizing `sreh-twin size --json --report` gives for the same inputs
// (sizing's public API: make_request, size, to_json), with what the page
// shows around it: the verdict block, plots, ISDU writes when the set is
// usable, and a way out of an infeasible answer.
#pragma once
#include <functional>
#include <optional>
#include <string>

#include "scenarios/load_file.hpp"
#include "sizing/sizing.hpp"
#include "sizing/uncertainty.hpp"
#include "studio/cycle_answer.hpp"
#include "studio/project.hpp"
#include "twin/load_figures.hpp"

namespace sreh::studio {

// The load (and mounting) as the project file holds it, read by the load
// files' parser; with `mass_scale` every part's mass multiplied. Throws
// ProjectError with the parser's message.
LoadFileContents parsed_load(const Json& state, double mass_scale = 1.0);

// A load over the limit is built with its masses scaled down (inertia and
// mass are linear in the masses, the centre of mass does not move) and its
// figures scaled back up (issue 37, A-STUDIO-2: show by how much, do not refuse).
inline constexpr double kOverLimitScale = 1e-3;

// The load's figures (twin/load_figures.hpp) as built with `mass_scale`
// (1, or kOverLimitScale for a load over the limit: divide masses, inertias
// and torques by it). Throws ProjectError for a load the parser or the
// twin refuses for another reason.
LoadFigures load_figures_of(const Json& state, double& mass_scale);

// Mass, inertia about the axis, centre of mass, gravity torque and each
// part's share. A load over the module's limit is not refused: its figures
// come with "over_by_gcm2" and the part with the largest share.
// Throws ProjectError for a part the load parser refuses.
Json load_panel(const Json& state);

// The request `size` would make for the state (the load as the project
// file holds it), with the trace kept as `size --report` keeps it.
sizing::SizingRequest sizing_request(const Json& state);

// A single move sized as `size` sizes it: with the uncertainty switch on,
// as `size --uncertainty` (its answer holds in every sample).
struct SingleSizing {
  sizing::SizingRequest request;
  sizing::SizingResult result;
  std::optional<sizing::UncertaintyResult> uncertainty;
};
SingleSizing size_single_state(const Json& state, const std::function<void()>& on_simulation = {});

// The `size` command line giving the same JSON object as the answer.
std::string answer_command(const Json& state);

// {"load": load_panel, "size": the size JSON (a cycle's: size --cycle's),
//  "command": the command line, "verdict_html", "plots_html", "writes":
//  [...], "writes_ready": bool, "uncertainty_html" (the switch on),
//  "way_out": {...} (infeasible only)} or, for input the sizing refuses,
// {"load": ..., "error": "..."}. Never throws for bad input.
// `on_simulation` is called as each simulation starts (the progress bar).
Json answer(const Json& state, const std::function<void()>& on_simulation = {});

// The CSV of an answer's figures (sizing/size_csv.hpp, as `size --csv`).
std::string answer_csv(const Json& state);
// The scenario replaying the sized move (`size --emit-scenario`).
std::string answer_scenario(const Json& state);
// `load show --picture` of the state's load (PNG bytes): from above and
// from the side, axis and centre of mass marked; a load over the limit too.
std::string load_picture_png(const Json& state);
// The printable page: `size --report`'s page with where it came from.
std::string answer_report(const Json& state, const std::string& version);

} // namespace sreh::studio
