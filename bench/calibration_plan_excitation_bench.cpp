// What a program of moves excites (issue 36, docs/calibration.md "What a
// plan can excite"): the table `calibrate --plan` prints (A-CAL-13), for any
// scenario, on the card with constants set as asked. It measures a plan
// change before the plan is changed: a segment added to the plan should
// raise its constant's change above the replay's jitter.
//
//   calibration_plan_excitation_bench PLAN.yaml [NAME=VALUE ...]
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "calibration/fit.hpp"
#include "calibration/plan_sensitivity.hpp"
#include "scenarios/scenario_parser.hpp"

int main(int argc, char** argv) {
  using namespace sreh;
  if (argc < 2 || std::string(argv[1]) == "--help") {
    std::fputs("usage: calibration_plan_excitation_bench PLAN.yaml [NAME=VALUE ...]\n", argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  ModelCard card = default_model_card();
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    const auto eq = a.find('=');
    ModelConstant* c = nullptr;
    for (ModelConstant& k : card.constants) {
      if (eq != std::string::npos && k.name == a.substr(0, eq)) c = &k;
    }
    char* end = nullptr;
    const std::string value = c ? a.substr(eq + 1) : "";
    const double v = std::strtod(value.c_str(), &end);
    if (!c || value.empty() || *end != '\0') {
      std::fprintf(stderr, "calibration_plan_excitation_bench: argument %d, %s: not NAME=VALUE of a card constant\n", i,
                   a.c_str());
      return 2;
    }
    c->value = v;
  }
  std::vector<std::string> names = default_fit_names();
  names.insert(names.end(), {"rotor_inertia", "velocity_bandwidth", "integral_ratio"});
  try {
    std::cout << format_plan_sensitivity(plan_sensitivity(parse_scenario_file(argv[1]), card, names, 2));
  } catch (const std::exception& e) { // the plan file does not read: say so, nothing printed
    std::fprintf(stderr, "calibration_plan_excitation_bench: %s\n", e.what());
    return 2;
  }
  return 0;
}
