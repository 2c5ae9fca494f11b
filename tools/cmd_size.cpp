// `sreh-twin size`: PerfectCycle-style sizing of one move back and forth
// (interfaces.md, manual 3.5.1), or of a multi-segment cycle (--cycle).
// Evaluates the set given with --speed-dps / --accel-pct / --jerk-pct, or
// recommends the fastest feasible one.
// Exit 0 feasible, 1 infeasible, 2 bad input (a value outside the module's
// limits, an unreadable load file); with --uncertainty 0 only when feasible
// on the nominal model and in every sample (A-SIZE-UNC-2).
#include <iostream>
#include <memory>

#include "sizing/output.hpp"
#include "sizing/size_options.hpp"
#include "tools/command.hpp"
#include "tools/option_table_cli.hpp"

namespace sreh::tools {
namespace {

struct SizeArgs {
  sizing::SizeOptions options;
  bool json = false;
};

int size_command(const SizeArgs& a) {
  sizing::SizeOutcome out;
  try {
    out = sizing::run_size(a.options);
  } catch (const sizing::SizingInputError& e) {
    throw InputError(e.what());
  }
  if (a.json) std::cout << out.json.dump(2) << "\n";
  else std::cout << out.text;
  return out.feasible ? 0 : 1;
}

} // namespace

SREH_REGISTER_COMMAND(30, [](CLI::App& app, int& exit_code) {
  auto a = std::make_shared<SizeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "size", "Size one move back and forth (or a multi-segment cycle, --cycle) like Afag's PerfectCycle: times, "
              "torque, temperature, a recommended parameter set (exit 0 feasible, 1 infeasible, 2 bad input; with "
              "--uncertainty 0 only when feasible on the nominal model and in every sample)");
  add_table_options(cmd, sizing::size_option_table(), a->options);
  cmd->get_option("--load-gcm2")->excludes("--load");
  cmd->get_option("--load")->excludes("--load-gcm2");
  cmd->add_flag("--json", a->json, "Print one JSON object on stdout");
  cmd->callback([a, &exit_code] { exit_code = size_command(*a); });
});

} // namespace sreh::tools
