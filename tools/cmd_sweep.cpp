// `sreh-twin sweep`: sizing over a grid, loads x angles x voltages x speeds
// (interfaces.md), each point one `size` (the given speed evaluated, or a set
// recommended), on several threads with a deterministic CSV. Exit 0 when the
// sweep ran (infeasible points are results, listed in the CSV), 2 bad input.
#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/output_path.hpp"
#include "io/shard.hpp"
#include "io/text.hpp"
#include "sizing/sweep.hpp"

#include <fmt/format.h>

#include "sizing/sweep_options.hpp"
#include "tools/command.hpp"
#include "tools/option_table_cli.hpp"
#include "tools/progress.hpp"

namespace sreh::tools {
namespace {

int sweep_command(const sizing::SweepOptions& a, bool quiet) {
  sizing::SweepResult result;
  int threads = 0;
  try {
    sizing::SweepRequest rq = sizing::make_sweep_request(a);
    threads = rq.threads;
    // Progress on stderr (issue 29): redrawn on a terminal, percent and ETA
    // lines in a CI log for a sweep over 2 s; never on stdout.
    Progress progress(isatty(STDERR_FILENO) != 0, quiet);
    progress.phase("sweeping");
    rq.progress = [&progress](std::size_t done, std::size_t total) {
      progress.update(static_cast<double>(done) / static_cast<double>(total));
    };
    result = sizing::run_sweep_command(a, rq);
    progress.end_phase();
  } catch (const sizing::SizingInputError& e) {
    throw InputError(e.what());
  }
  // After the run: bad input stays one line on stderr (exit 2).
  const std::string note = io::one_task_array_note(a.shard, [](const char* n) -> const char* { return std::getenv(n); });
  if (!note.empty()) std::cerr << "sreh-twin: " << note << "\n";
  std::size_t feasible = 0;
  for (const auto& p : result.points) feasible += p.result.evaluation.feasible ? 1 : 0;
  // The thread count shows what the default found (issue 31: a batch job's CPUs, not the node's).
  std::cout << fmt::format("{} points, {} feasible, {} thread{}: {}\n", result.points.size(), feasible, threads,
                           threads == 1 ? "" : "s", a.csv);
  return 0;
}

// CLI11's Range says "Value  not in range" for `--threads "$SLURM_CPUS_PER_TASK"`
// with the variable unset (issue 31): name the value and the way out.
std::string check_threads(const std::string& value) {
  int n = 0;
  const auto r = std::from_chars(value.data(), value.data() + value.size(), n);
  if (r.ec == std::errc() && r.ptr == value.data() + value.size() && n >= 1 && n <= 64) return "";
  return fmt::format("'{}' is not a whole number 1 .. 64{}", io::escape_control(value),
                     value.empty() ? " (an unset variable such as SLURM_CPUS_PER_TASK? leave --threads out: the default "
                                     "is the CPUs this process may use, fewer if SLURM_CPUS_PER_TASK says so)"
                                   : "");
}

int merge_command(const std::string& csv, const std::vector<std::string>& parts) {
  try {
    io::check_outputs({{"--csv", csv, io::OutputKind::File}}, parts); // the one output rule (issue 12)
    io::write_file_atomic(csv, [&](std::ostream& out) { sizing::merge_sweep_csv(out, parts); });
  } catch (const sizing::SizingInputError& e) {
    throw InputError(e.what());
  } catch (const io::PathError& e) {
    throw InputError(e.what());
  }
  std::cout << fmt::format("{} parts merged: {}\n", parts.size(), csv);
  return 0;
}

} // namespace

SREH_REGISTER_COMMAND(31, [](CLI::App& app, int& exit_code) {
  auto a = std::make_shared<sizing::SweepOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sweep", "Sizing over a grid of loads x angles x voltages (x speeds): CSV and plots (exit 0 ran, 2 bad input)");
  add_table_options(cmd, sizing::sweep_option_table(), *a);
  cmd->get_option("--threads")->check(CLI::Validator(check_threads, "1..64"));
  // `sweep merge --csv OUT PART...` (issue 17): the grid options are then
  // not needed, so they are checked in the callback rather than by CLI11.
  cmd->get_option("--loads-gcm2")->required(false);
  cmd->get_option("--angles-deg")->required(false);
  auto quiet = std::make_shared<bool>(false);
  cmd->add_flag("--quiet", *quiet, "No progress lines on stderr (they come for work over 2 s)");
  auto parts = std::make_shared<std::vector<std::string>>();
  auto merged = std::make_shared<std::string>();
  CLI::App* merge = cmd->add_subcommand(
      "merge", "Join the CSVs of `sweep --shard i/N` (one or more) into the unsharded CSV (byte-identical)");
  merge->add_option("--csv", *merged, "Write the merged CSV here")->required();
  merge->add_option("parts", *parts, "The part CSVs, any order")->required();
  merge->callback([parts, merged, &exit_code] { exit_code = merge_command(*merged, *parts); });
  cmd->callback([a, merge, quiet, &exit_code] {
    if (merge->parsed()) return;
    if (a->csv.empty()) throw CLI::RequiredError("--csv"); // the CLI's output (Python returns the columns)
    if (a->loads_gcm2.empty()) throw CLI::RequiredError("--loads-gcm2");
    if (a->angles_deg.empty()) throw CLI::RequiredError("--angles-deg");
    exit_code = sweep_command(*a, *quiet);
  });
});

} // namespace sreh::tools
