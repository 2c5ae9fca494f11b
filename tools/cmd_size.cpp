// `sreh-twin size`: PerfectCycle-style sizing of one move back and forth
// (interfaces.md, manual 3.5.1), or of a multi-segment cycle (--cycle).
// Evaluates the set given with --speed-dps / --accel-pct / --jerk-pct, or
// recommends the fastest feasible one.
// Exit 0 feasible, 1 infeasible, 2 bad input (a value outside the module's
// limits, an unreadable load file); with --uncertainty 0 only when feasible
// on the nominal model and in every sample (A-SIZE-UNC-2).
#include <unistd.h>

#include <atomic>
#include <iostream>
#include <memory>
#include <mutex>

#include "sizing/output.hpp"
#include "sizing/size_options.hpp"
#include "tools/command.hpp"
#include "tools/option_table_cli.hpp"
#include "tools/progress.hpp"

namespace sreh::tools {
namespace {

struct SizeArgs {
  sizing::SizeOptions options;
  bool json = false;
  bool quiet = false; // no progress lines on stderr
};

int size_command(const SizeArgs& a) {
  sizing::SizeOutcome out;
  // Progress on stderr (issue 39): a search or --uncertainty runs dozens of
  // simulations; their count, as their number is not known ahead.
  Progress progress(isatty(STDERR_FILENO) != 0, a.quiet);
  progress.phase("sizing");
  std::mutex mutex;
  uint64_t simulations = 0;
  sizing::SizeOptions options = a.options;
  options.on_simulation = [&] {
    const std::lock_guard lock(mutex);
    progress.update_count(++simulations, "simulations");
  };
  try {
    out = sizing::run_size(options);
    progress.end_phase();
  } catch (const sizing::SizingInputError& e) {
    throw InputError(e.what());
  }
  if (a.json) {
    std::cout << out.json.dump(2) << "\n";
  } else {
    std::cout << out.text;
    // Issue 39: a success line per file written.
    if (!a.options.report.empty()) std::cout << "wrote " << a.options.report << "/index.html\n";
    if (!a.options.emit_scenario.empty()) std::cout << "wrote " << a.options.emit_scenario << "\n";
  }
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
  cmd->add_flag("--quiet", a->quiet, "No progress lines on stderr (they come for work over 2 s)");
  cmd->callback([a, &exit_code] { exit_code = size_command(*a); });
});

} // namespace sreh::tools
