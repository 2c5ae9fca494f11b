// The `run --json` object (interfaces.md): passed, failures, moves, final,
// plus checks and run statistics.
#pragma once
#include <nlohmann/json.hpp>

#include "scenarios/runner.hpp"

namespace sreh {

nlohmann::json to_json(const RunResult& result);
// One move record as in `moves[]` (also used by the Python API and serve).
nlohmann::json move_json(const MoveRecord& move);
// One check record as in `checks[]`.
nlohmann::json check_json(const CheckRecord& check);

} // namespace sreh
