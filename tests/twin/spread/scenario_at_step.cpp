// Issue 35 part 4: a shipped scenario passes at a finer physics step too.
// usage: scenario_at_step SCENARIO.yaml PHYSICS_DT_S
// Runs the scenario with sim.physics_dt_s replaced (it must divide the
// scenario's own step, so every cycle and control period still fits);
// exit 0 passed, 1 failed (the failures on stderr), 2 bad input.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include "scenarios/runner.hpp"
#include "scenarios/scenario_parser.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: scenario_at_step SCENARIO.yaml PHYSICS_DT_S\n");
    return 2;
  }
  const std::string dt_text = argv[2];
  double dt_s = 0;
  const auto [end, ec] = std::from_chars(dt_text.data(), dt_text.data() + dt_text.size(), dt_s);
  if (ec != std::errc() || end != dt_text.data() + dt_text.size() || !(dt_s > 0)) {
    std::fprintf(stderr, "scenario_at_step: PHYSICS_DT_S '%s' is not a positive number\n", argv[2]);
    return 2;
  }
  try {
    sreh::Scenario s = sreh::parse_scenario_file(argv[1]);
    const double ratio = s.world.physics_dt_s / dt_s;
    if (std::abs(ratio - std::round(ratio)) > 1e-9 * ratio || ratio < 1) {
      std::fprintf(stderr, "scenario_at_step: %g s does not divide the scenario's step %g s\n", dt_s,
                   s.world.physics_dt_s);
      return 2;
    }
    s.world.physics_dt_s = dt_s;
    const sreh::RunResult r = sreh::run_scenario(s);
    for (const std::string& f : r.failures) std::fprintf(stderr, "%s\n", f.c_str());
    std::printf("%s at %g ms: %s\n", r.name.c_str(), dt_s * 1e3, r.passed ? "passed" : "FAILED");
    return r.passed ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
}
