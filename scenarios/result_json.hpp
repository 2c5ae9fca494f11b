// The `run --json` object (interfaces.md): passed, failures, moves, final,
// plus checks and run statistics.
#pragma once
#include <nlohmann/json.hpp>

#include "scenarios/runner.hpp"

namespace sreh {

nlohmann::json to_json(const RunResult& result);

} // namespace sreh
