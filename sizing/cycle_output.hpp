// Output of `sreh-twin size --cycle`: the JSON object, the summary text and
// the emitted scenario that replays the cycle in the twin (--emit-scenario).
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sizing/cycle.hpp"

namespace sreh::sizing {

struct UncertaintyResult; // sizing/uncertainty.hpp

// Every ISDU write of every set, each (index, subindex) once.
std::vector<IsduWrite> all_writes(const CycleEvaluation& evaluation);

// With `u` (--uncertainty): `feasible` is the verdict over every sample
// (A-SIZE-UNC-2), `feasible_nominal` the nominal run's, and the bands follow.
nlohmann::json cycle_to_json(const CycleRequest& request, const CycleResult& result, const UncertaintyResult* u = nullptr);
std::string cycle_summary_text(const CycleRequest& request, const CycleResult& result, const UncertaintyResult* u = nullptr);

// A scenario (scenarios/README.md) replaying the cycle: the sets written at
// start-up (device.isdu), load, mounting, supply, ambient; Motor On; the
// segments `request.cycles` times (repeat:), each move checked (Done in
// time, no error, inside its tolerance window), process torques as
// `torque` steps, load changes as `load` steps; at the end the number of
// moves completed. `set_of_segment[i]`: the set number a move uses (-1 for
// other segments); `sets` the values written.
std::string scenario_yaml(const CycleRequest& request, const std::vector<ParameterSetValues>& sets,
                          const std::vector<int>& set_of_segment, const std::string& name);

// The single move of `size` as the cycle it runs: 0 -> A (dwell) -> 0 (dwell).
CycleRequest cycle_of_single(const SizingRequest& request);

// Writes `yaml` atomically (io::write_file_atomic); the path was checked
// with the output rule before.
void write_scenario_file(const std::string& path, const std::string& yaml);

} // namespace sreh::sizing
