// Resource limits of a scenario run (issue 12): a file cannot make the tool
// use unbounded memory, time or disk. Every limit has a default above every
// shipped scenario and the soak benchmark, and a `run` option to raise it
// (scenarios/README.md "Limits"). Exceeding one is bad input: exit 2 with a
// message naming the file (line:column) and the option.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace sreh {

struct Scenario;

struct Limits {
  std::size_t max_file_bytes = 4u << 20;      // --max-file-mb: scenario / load files
  std::size_t max_yaml_nodes = 200000;        // --max-yaml-nodes: after alias expansion
  int max_yaml_depth = 64;                    // --max-yaml-depth: nested lists / mappings
  double max_sim_s = 3600.0;                  // --max-sim-s: simulated time of a run
  uint64_t max_steps = 10'000'000;            // --max-steps: executed steps (repeats unrolled)
  uint64_t max_checks = 1'000'000;            // --max-checks: recorded checks (kept for the result)
  uint64_t max_trace_bytes = uint64_t{2} << 30; // --max-trace-mb: CSV trace on disk
};

// What a scenario can do at most (repeats at their full count, every
// wait_until to its `within_s`): known from the file, before running.
struct RunBound {
  double sim_s = 0;     // simulated seconds, whole IO-Link cycles
  double steps = 0;     // executed steps (double: a product of repeats may overflow integers)
  double checks = 0;    // recorded checks
};

RunBound run_bound(const Scenario& scenario);

// Throws ScenarioError naming the scenario line where the bound first
// exceeds a limit, and the option that raises it.
void check_run_bound(const Scenario& scenario, const Limits& limits);

} // namespace sreh
