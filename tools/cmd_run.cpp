// `sreh-twin run SCENARIO.yaml`: simulate a scenario and check its
// expectations (interfaces.md). Exit 0 all held, 1 a check failed, 2 bad input.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <regex>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "scenarios/atomic_file.hpp"
#include "scenarios/result_json.hpp"
#include "scenarios/runner.hpp"
#include "scenarios/scenario_parser.hpp"
#include "tools/command.hpp"
#include "twin/trace.hpp"

namespace sreh::tools {
namespace {

struct RunArgs {
  std::string scenario;
  std::string trace;
  int trace_every = 1;
  bool json = false;
  std::string video;
  int fps = 30;
  std::string size = "640x480";
  std::string report;
  std::string save_nvm;
};

// Progress on stderr, only for a person watching (a TTY) and only once a run
// has taken more than a second of wall time. Wall time is the CLI's business
// only; the simulation never reads it.
class Progress {
 public:
  explicit Progress(bool enabled) : enabled_(enabled), start_(Clock::now()), last_(start_) {}
  void update(double t_s) {
    if (!enabled_ || (++calls_ % 50) != 0) return;
    const auto now = Clock::now();
    if (now - start_ < std::chrono::seconds(1) || now - last_ < std::chrono::milliseconds(200)) return;
    last_ = now;
    shown_ = true;
    std::fprintf(stderr, "\rsimulated %.2f s", t_s);
    std::fflush(stderr);
  }
  ~Progress() {
    if (shown_) std::fprintf(stderr, "\r%30s\r", "");
  }

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  Clock::time_point start_, last_;
  uint64_t calls_ = 0;
  bool shown_ = false;
};

void check_output(const std::string& path, const char* option) {
  if (!path.empty() && !output_folder_exists(path)) {
    throw InputError(fmt::format("{} {}: the folder does not exist", option, path));
  }
}

void write_outputs(const RunArgs& a, const RunResult& r) {
  try {
    if (!a.trace.empty()) {
      std::vector<TraceRow> rows;
      for (std::size_t i = 0; i < r.trace.size(); i += static_cast<std::size_t>(a.trace_every)) rows.push_back(r.trace[i]);
      write_file_atomic(a.trace, [&](std::ostream& out) { write_trace_csv(out, rows); });
    }
    if (!a.save_nvm.empty()) {
      write_file_atomic(a.save_nvm, [&](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(r.nvm_image.data()), static_cast<std::streamsize>(r.nvm_image.size()));
      });
    }
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }
}

void print_summary(const RunResult& r) {
  std::cout << (r.passed ? "PASS" : "FAIL") << "  " << r.name << "\n";
  for (const auto& f : r.failures) std::cout << "  " << f << "\n";
  std::size_t passed = 0;
  for (const auto& c : r.checks) passed += c.passed ? 1 : 0;
  std::cout << fmt::format("  {} of {} checks held, {} moves, {:.3f} s simulated{}\n", passed, r.checks.size(),
                           r.moves.size(), r.sim_time_s, r.stopped_early ? " (stopped at the first failure)" : "");
  std::cout << fmt::format("  final: {} at {:.3f} deg, error_code {}, warning_code {}\n",
                           state_name(r.final_state.state), r.final_state.position_deg, r.final_state.error_code,
                           r.final_state.warning_code);
}

int run_command(const RunArgs& a) {
  // Renders are wired in by the renders work (issue 7); until then the options
  // exist but refuse, so that scripts fail loudly rather than silently.
  if (!a.video.empty()) throw InputError("--video: not yet available");
  if (!a.report.empty()) throw InputError("--report: not yet available");
  if (!std::regex_match(a.size, std::regex("[1-9][0-9]{1,4}x[1-9][0-9]{1,4}"))) {
    throw InputError(fmt::format("--size {}: expected WIDTHxHEIGHT, e.g. 640x480", a.size));
  }
  check_output(a.trace, "--trace");
  check_output(a.save_nvm, "--save-nvm");

  RunResult result;
  try {
    const Scenario scenario = parse_scenario_file(a.scenario);
    Progress progress(isatty(STDERR_FILENO) != 0);
    RunOptions options;
    options.record_trace = !a.trace.empty();
    options.on_cycle = [&](const Twin& twin) { progress.update(twin.time_s()); };
    result = run_scenario(scenario, options);
  } catch (const ScenarioError& e) {
    throw InputError(e.what());
  }
  write_outputs(a, result);
  if (a.json) {
    std::cout << to_json(result).dump(2) << "\n";
  } else {
    print_summary(result);
  }
  return result.passed ? 0 : 1;
}

} // namespace

SREH_REGISTER_COMMAND(10, [](CLI::App& app, int& exit_code) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* cmd = app.add_subcommand("run", "Simulate a scenario and check its expectations (exit 0 held, 1 failed, 2 bad input)");
  cmd->add_option("scenario", args->scenario, "Scenario file (YAML, see scenarios/README.md)")->required();
  cmd->add_option("--trace", args->trace, "Write a CSV trace, one row per IO-Link cycle");
  cmd->add_option("--trace-every", args->trace_every, "Keep every Nth cycle in the trace")->check(CLI::Range(1, 1000000));
  cmd->add_flag("--json", args->json, "Print one JSON object with the results on stdout");
  cmd->add_option("--video", args->video, "Render an MP4 video of the run");
  cmd->add_option("--fps", args->fps, "Video frames per second")->check(CLI::Range(1, 240));
  cmd->add_option("--size", args->size, "Video size WIDTHxHEIGHT");
  cmd->add_option("--report", args->report, "Write an HTML report with plots into this folder");
  cmd->add_option("--save-nvm", args->save_nvm, "Save the device's non-volatile memory at the end to this file");
  cmd->callback([args, &exit_code] { exit_code = run_command(*args); });
});

} // namespace sreh::tools
