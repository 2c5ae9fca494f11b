// `sreh-twin sweep`: sizing over a grid, loads x angles x voltages x speeds
// (interfaces.md), each point one `size` (the given speed evaluated, or a set
// recommended), on several threads with a deterministic CSV. Exit 0 when the
// sweep ran (infeasible points are results, listed in the CSV), 2 bad input.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "scenarios/atomic_file.hpp"
#include "sizing/report.hpp"
#include "sizing/sweep.hpp"
#include "tools/command.hpp"

namespace sreh::tools {
namespace {

struct SweepArgs {
  std::vector<double> loads_gcm2, angles_deg, voltages_V{24.0}, speeds_dps, targets_s;
  double accel_pct = 100.0, jerk_pct = 100.0;
  double dwell_s = 0.0, tolerance_deg = 0.1, wait_ms = 25.0, ambient_C = 25.0;
  std::optional<double> timeout_ms;
  int cycles = 2;
  int threads = 0; // 0: one per core
  std::string csv, report;
};

int sweep_command(const SweepArgs& a) {
  if (!output_folder_exists(a.csv)) throw InputError(fmt::format("--csv {}: the folder does not exist", a.csv));
  if (!a.report.empty() && !sizing::reports_available()) throw InputError("--report: this build has no renders");
  for (double t : a.targets_s) {
    if (!(t > 0)) throw InputError(fmt::format("--targets-s {}: target times must be positive", t));
  }
  sizing::SweepRequest rq;
  rq.loads_gcm2 = a.loads_gcm2;
  rq.angles_deg = a.angles_deg;
  rq.voltages_V = a.voltages_V;
  rq.speeds_dps = a.speeds_dps;
  rq.accel_pct = a.accel_pct;
  rq.jerk_pct = a.jerk_pct;
  rq.base.dwell_s = a.dwell_s;
  rq.base.tolerance_deg = a.tolerance_deg;
  rq.base.wait_ms = a.wait_ms;
  rq.base.timeout_ms = a.timeout_ms;
  rq.base.ambient_C = a.ambient_C;
  rq.base.cycles = a.cycles;
  rq.threads = a.threads > 0 ? a.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  // Progress for a person watching only (stderr a TTY); never on stdout.
  const bool tty = isatty(STDERR_FILENO) != 0;
  if (tty) {
    rq.progress = [](std::size_t done, std::size_t total) {
      std::fprintf(stderr, "\rsweep: %zu / %zu points", done, total);
      if (done == total) std::fprintf(stderr, "\r%40s\r", "");
      std::fflush(stderr);
    };
  }
  sizing::SweepResult result;
  try {
    result = sizing::run_sweep(rq);
  } catch (const sizing::SizingInputError& e) {
    throw InputError(e.what());
  }
  try {
    write_file_atomic(a.csv, [&](std::ostream& out) { sizing::write_sweep_csv(out, result); });
    if (!a.report.empty()) {
      const std::vector<double> targets = a.targets_s.empty() ? sizing::default_targets_s(result) : a.targets_s;
      sizing::write_sweep_report(a.report, rq, result, targets);
    }
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }
  std::size_t feasible = 0;
  for (const auto& p : result.points) feasible += p.result.evaluation.feasible ? 1 : 0;
  std::cout << fmt::format("{} points, {} feasible: {}\n", result.points.size(), feasible, a.csv);
  return 0;
}

} // namespace

SREH_REGISTER_COMMAND(31, [](CLI::App& app, int& exit_code) {
  auto a = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sweep", "Sizing over a grid of loads x angles x voltages (x speeds): CSV and plots (exit 0 ran, 2 bad input)");
  cmd->add_option("--loads-gcm2", a->loads_gcm2, "Load inertias, comma separated, 0 .. 15000 g cm^2")
      ->delimiter(',')->required();
  cmd->add_option("--angles-deg", a->angles_deg, "Move angles in deg, comma separated")->delimiter(',')->required();
  cmd->add_option("--voltages-V", a->voltages_V, "Supply voltages 16 .. 32 V, comma separated")
      ->delimiter(',')->capture_default_str();
  cmd->add_option("--speeds-dps", a->speeds_dps, "Evaluate these speeds in deg/s (comma separated) instead of recommending [default: recommend]")
      ->delimiter(',');
  cmd->add_option("--accel-pct", a->accel_pct, "Acceleration with --speeds-dps, 0.1 .. 100 %")->capture_default_str();
  cmd->add_option("--jerk-pct", a->jerk_pct, "Jerk with --speeds-dps, 0.1 .. 100 %")->capture_default_str();
  cmd->add_option("--dwell-s", a->dwell_s, "Pause after each move, s")->capture_default_str();
  cmd->add_option("--tolerance-deg", a->tolerance_deg, "Position tolerance in deg (index 64+n.5)")->capture_default_str();
  cmd->add_option("--wait-ms", a->wait_ms, "Waiting time in ms (index 64+n.6)")->capture_default_str();
  cmd->add_option("--timeout-ms", a->timeout_ms, "Settling timeout in ms (index 64+n.7) [default: wait + 75 ms, >= 100 ms]");
  cmd->add_option("--ambient-C", a->ambient_C, "Ambient temperature, degC")->capture_default_str();
  cmd->add_option("--cycles", a->cycles, "Back-and-forth cycles simulated per evaluation")->capture_default_str();
  cmd->add_option("--threads", a->threads, "Worker threads, 1 .. 64 [default: one per core]")->check(CLI::Range(1, 64));
  cmd->add_option("--csv", a->csv, "Write the results to this CSV file (one row per grid point)")->required();
  cmd->add_option("--report", a->report, "Write an HTML report with plots into this folder");
  cmd->add_option("--targets-s", a->targets_s, "Target positioning times in s for the heaviest-load plot, comma separated [default: 8 spanning the feasible times]")
      ->delimiter(',');
  cmd->callback([a, &exit_code] { exit_code = sweep_command(*a); });
});

} // namespace sreh::tools
