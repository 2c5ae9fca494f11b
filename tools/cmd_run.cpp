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
#include "twin/plant.hpp"
#include "twin/trace.hpp"
#ifdef SREH_WITH_RENDER
#include "renders/report.hpp"
#include "renders/video.hpp"
#endif

namespace sreh::tools {
namespace {

struct RunArgs {
  std::string scenario;
  std::string trace;
  int trace_every = 1;
  bool json = false;
  std::string video;
  int fps = 30;
  std::string size = "1280x720";
  double slowmo = 1.0;
  std::string frames;
  std::string camera = "default";
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

#ifdef SREH_WITH_RENDER
// Video frames are taken on IO-Link cycle boundaries (issue 7), by integer
// frame index inside the recorder; the recorder is made when the twin exists.
class VideoHook {
 public:
  explicit VideoHook(VideoOptions options) : options_(std::move(options)) {}
  void on_cycle(const Twin& twin) {
    const Plant& plant = twin.plant();
    if (!recorder_) recorder_ = std::make_unique<VideoRecorder>(plant.model(), options_);
    if (!recorder_->wants_frame(twin.time_s())) return;
    const Telemetry t = twin.telemetry();
    FrameInfo info;
    info.t_s = twin.time_s();
    info.state = t.state;
    info.position_deg = t.position_deg;
    info.setpoint_deg = t.setpoint_deg;
    info.tracking_error_deg = t.tracking_error_deg;
    info.error_code = t.error_code;
    info.warning_code = t.warning_code;
    info.led = t.led;
    info.ghost_joint_rad = plant.ghost_angle_rad();
    recorder_->add_frame(plant.model(), plant.data(), info);
  }
  void finish() {
    if (recorder_) recorder_->finish();
  }

 private:
  VideoOptions options_;
  std::unique_ptr<VideoRecorder> recorder_;
};

VideoOptions video_options(const RunArgs& a) {
  VideoOptions v;
  v.path = a.video;
  v.frames_dir = a.frames;
  v.fps = a.fps;
  v.slowmo = a.slowmo;
  const auto x = a.size.find('x');
  v.width_px = std::stoi(a.size.substr(0, x));
  v.height_px = std::stoi(a.size.substr(x + 1));
  if (v.width_px % 2 != 0 || v.height_px % 2 != 0) {
    throw InputError(fmt::format("--size {}: width and height must be even (H.264, yuv420p)", a.size));
  }
  if (a.camera == "top") v.camera = CameraSpec::top();
  return v;
}

void write_report_dir(const RunArgs& a, const RunResult& r) {
  ReportInput in;
  in.scenario_name = r.name;
  in.passed = r.passed;
  for (const auto& c : r.checks) in.checks.push_back({fmt::format("step {} (line {}): {}", c.step, c.line, c.description), c.passed});
  in.trace = r.trace;
  in.moves = r.moves;
  in.tracking_limit_deg = r.tracking_limit_deg;
  if (!a.video.empty()) {
    namespace fs = std::filesystem;
    in.video_file = fs::relative(fs::absolute(a.video), fs::absolute(a.report)).generic_string();
  }
  try {
    write_report(a.report, in);
  } catch (const std::exception& e) {
    throw InputError(fmt::format("--report {}: {}", a.report, e.what()));
  }
}
#endif

int run_command(const RunArgs& a) {
#ifndef SREH_WITH_RENDER
  if (!a.video.empty() || !a.frames.empty()) throw InputError("--video: built without rendering (SREH_WITH_RENDER=OFF)");
  if (!a.report.empty()) throw InputError("--report: built without rendering (SREH_WITH_RENDER=OFF)");
#endif
  if (!std::regex_match(a.size, std::regex("[1-9][0-9]{1,4}x[1-9][0-9]{1,4}"))) {
    throw InputError(fmt::format("--size {}: expected WIDTHxHEIGHT, e.g. 1280x720", a.size));
  }
  check_output(a.trace, "--trace");
  check_output(a.save_nvm, "--save-nvm");
  check_output(a.video, "--video");
  check_output(a.report, "--report");
  if (a.camera != "default" && a.camera != "top") {
    throw InputError(fmt::format("--camera {}: expected default or top", a.camera));
  }

  RunResult result;
  try {
    const Scenario scenario = parse_scenario_file(a.scenario);
    Progress progress(isatty(STDERR_FILENO) != 0);
    RunOptions options;
    options.record_trace = !a.trace.empty() || !a.report.empty();
#ifdef SREH_WITH_RENDER
    std::optional<VideoHook> video;
    if (!a.video.empty() || !a.frames.empty()) video.emplace(video_options(a));
    options.on_cycle = [&](const Twin& twin) {
      if (video) video->on_cycle(twin);
      progress.update(twin.time_s());
    };
    result = run_scenario(scenario, options);
    if (video) video->finish();
#else
    options.on_cycle = [&](const Twin& twin) { progress.update(twin.time_s()); };
    result = run_scenario(scenario, options);
#endif
  } catch (const ScenarioError& e) {
    throw InputError(e.what());
  }
  write_outputs(a, result);
#ifdef SREH_WITH_RENDER
  if (!a.report.empty()) write_report_dir(a, result);
#endif
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
  cmd->add_option("--size", args->size, "Video size WIDTHxHEIGHT (even numbers)")->capture_default_str();
  cmd->add_option("--slowmo", args->slowmo, "Play the video this many times slower than simulated time")
      ->check(CLI::Range(0.01, 1000.0));
  cmd->add_option("--frames", args->frames, "Also write PNG frames into this folder");
  cmd->add_option("--camera", args->camera, "Camera: default (frames module and load) or top")->capture_default_str();
  cmd->add_option("--report", args->report, "Write an HTML report with plots into this folder");
  cmd->add_option("--save-nvm", args->save_nvm, "Save the device's non-volatile memory at the end to this file");
  cmd->callback([args, &exit_code] { exit_code = run_command(*args); });
});

} // namespace sreh::tools
