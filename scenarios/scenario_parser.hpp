// YAML -> Scenario (docs/style.md 13: strict loading at the edge). Unknown keys,
// wrong types, out-of-range values, missing files: ScenarioError with
// "FILE:LINE:COL: what is wrong". Key reference: scenarios/README.md.
#pragma once
#include <string>

#include "scenarios/limits.hpp"
#include "scenarios/scenario.hpp"

namespace sreh {

// Reads and parses a scenario file. Relative paths inside it (MJCF loads,
// NVM images) are resolved against the file's folder.
// Limits (file size, YAML nodes and depth) as in scenarios/limits.hpp.
Scenario parse_scenario_file(const std::string& path, const Limits& limits = {});

// Parses YAML text; `file` names it in messages, `base_dir` resolves
// relative paths ("" = current directory).
Scenario parse_scenario_text(const std::string& yaml_text, const std::string& file,
                             const std::string& base_dir, const Limits& limits = {});

// `run --model FILE` (issue 25): the file's overrides of the model card on
// top of the scenario's own `model:` (the command line wins). Throws
// ScenarioError naming the model file's line, or the scenario when its
// sim clocks no longer fit the drive's control period.
void apply_command_line_model(Scenario& s, const std::string& model_path);

} // namespace sreh
