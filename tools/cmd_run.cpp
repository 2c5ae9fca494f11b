// `sreh-twin run SCENARIO.yaml`: simulate a scenario and check its
// expectations (interfaces.md). Exit 0 all held, 1 a check failed, 2 bad input.
// `run DIR`: a folder of them (tools/run_folder.cpp).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <regex>
#include <string>

#include <fmt/format.h>

#include "io/atomic_file.hpp"
#include "io/output_path.hpp"
#include "scenarios/limits.hpp"
#include "scenarios/runner.hpp"
#include "scenarios/scenario_parser.hpp"
#include "tools/command.hpp"
#include "tools/junit_report.hpp"
#include "tools/progress.hpp"
#include "tools/master_log_stream.hpp"
#include "tools/run_folder.hpp"
#include "tools/run_output.hpp"
#include "twin/load_builder.hpp"
#include "twin/plant.hpp"
#include "twin/trace.hpp"
#ifdef SREH_WITH_RENDER
#include "renders/ffmpeg_encoder.hpp"
#include "renders/run_media.hpp"
#endif

namespace sreh::tools {
namespace {

constexpr int kMinVideoSide = 16;
constexpr int kMaxVideoSide = 4096;

struct RunArgs {
  std::string scenario;
  std::string trace;
  int trace_every = 1;
  bool json = false;
  std::string video;
  int fps = 30;
  std::string size = "1280x720";
  double slowmo = 0; // 0: automatic time scaling
  std::string frames;
  std::string camera = "default";
  std::string report;
  std::string save_nvm;
  Limits limits;
  uint64_t max_trace_mb = 2048;
  uint64_t max_file_mb = 4;
  std::string shard; // with a folder
  std::string model; // --model FILE (issue 25)
  std::string junit; // --junit FILE (issue 29)
  bool quiet = false; // no progress lines on stderr
  std::string master_log; // --master-log FILE.csv (issue 26)
};

// --trace: rows go to the file's temporary as the run makes them (memory
// flat with run length, issue 12); the same bytes as write_trace_csv over the
// whole trace in memory. Committed only when the run finished.
class TraceStream {
 public:
  TraceStream(const std::string& path, int every, uint64_t max_bytes)
      : file_(path), every_(static_cast<uint64_t>(every)), max_bytes_(max_bytes) {
    write_trace_header(file_.stream());
  }
  void row(const TraceRow& r) {
    if (rows_++ % every_ != 0) return;
    write_trace_row(file_.stream(), r);
    if (static_cast<uint64_t>(file_.stream().tellp()) > max_bytes_) {
      throw InputError(fmt::format("--trace {}: the trace is larger than {} MB; raise the limit with --max-trace-mb "
                                   "or keep fewer rows with --trace-every", file_.path(), max_bytes_ >> 20));
    }
  }
  void commit() { file_.commit(); }

 private:
  io::AtomicFile file_;
  uint64_t every_;
  uint64_t max_bytes_;
  uint64_t rows_ = 0;
};

void write_nvm(const RunArgs& a, const RunResult& r) {
  if (a.save_nvm.empty()) return;
  io::write_file_atomic(a.save_nvm, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(r.nvm_image.data()), static_cast<std::streamsize>(r.nvm_image.size()));
  });
}

#ifdef SREH_WITH_RENDER
// The video and the report (renders/run_media.hpp): the run is recorded once
// per IO-Link cycle and rendered after it, when the moves are known: the
// time map slows the moves down and compresses idle stretches (issue 16),
// unless --slowmo fixes one factor.
RunMediaOptions media_options(const RunArgs& a) {
  RunMediaOptions m;
  if (!a.video.empty() || !a.frames.empty()) {
    VideoOptions v;
    v.path = a.video;
    v.frames_dir = a.frames;
    v.fps = a.fps;
    v.slowmo = a.slowmo > 0 ? a.slowmo : 1.0;
    const auto x = a.size.find('x'); // checked by check_size
    v.width_px = std::stoi(a.size.substr(0, x));
    v.height_px = std::stoi(a.size.substr(x + 1));
    if (a.camera == "top") v.camera = CameraSpec::top();
    m.video = v;
  }
  m.fixed_slowmo = a.slowmo > 0;
  m.report_dir = a.report;
  m.command_line = command_line();
  m.version = SREH_VERSION;
  return m;
}
#endif

// Video size: even (H.264 yuv420p) and within what the off-screen renderer
// can allocate (A-RENDERS-*: 16 .. 4096 pixels a side).
void check_size(const std::string& size) {
  if (!std::regex_match(size, std::regex("[1-9][0-9]{1,4}x[1-9][0-9]{1,4}"))) {
    throw InputError(fmt::format("--size {}: expected WIDTHxHEIGHT, e.g. 1280x720", size));
  }
  const auto x = size.find('x');
  const int w = std::stoi(size.substr(0, x));
  const int h = std::stoi(size.substr(x + 1));
  if (w < kMinVideoSide || h < kMinVideoSide || w > kMaxVideoSide || h > kMaxVideoSide) {
    throw InputError(fmt::format("--size {}: width and height must be {} .. {} pixels", size, kMinVideoSide, kMaxVideoSide));
  }
  if (w % 2 != 0 || h % 2 != 0) {
    throw InputError(fmt::format("--size {}: width and height must be even (H.264, yuv420p)", size));
  }
}

// The files a run reads: outputs may not be any of them.
// run_scenario with its wall time (issue 25: `run --json` reports it and
// the real-time factor; the simulation itself never reads a clock).
RunResult timed_run(const Scenario& scenario, const RunOptions& options, double& wall_s) {
  const auto start = std::chrono::steady_clock::now();
  RunResult result = run_scenario(scenario, options);
  wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::vector<std::string> inputs_of(const RunArgs& a, const Scenario& s) {
  std::vector<std::string> in{a.scenario};
  if (s.device.nvm_image_path) in.push_back(*s.device.nvm_image_path);
  if (!s.world.model_file.empty()) in.push_back(s.world.model_file);
  if (!a.model.empty()) in.push_back(a.model);
  for (const std::string& f : load_input_files(s.world.load)) in.push_back(f); // MJCF and mesh files
  return in;
}

// `run DIR` (issue 17): the options that write one file per run have no
// meaning for a folder and are refused; the limits apply to every file.
int run_folder_command(const RunArgs& a) {
  for (const auto& [option, value] : {std::pair<const char*, const std::string&>{"--trace", a.trace},
                                      {"--video", a.video},
                                      {"--frames", a.frames},
                                      {"--report", a.report},
                                      {"--save-nvm", a.save_nvm},
                                      {"--master-log", a.master_log}}) {
    if (!value.empty()) {
      throw InputError(fmt::format("{}: not with a folder of scenarios ({}); run one scenario file for it", option,
                                   a.scenario));
    }
  }
  FolderArgs f;
  f.dir = a.scenario;
  f.shard = a.shard;
  f.json = a.json;
  f.limits = a.limits;
  f.model = a.model;
  f.junit = a.junit;
  f.limits.max_trace_bytes = a.max_trace_mb << 20;
  f.limits.max_file_bytes = static_cast<std::size_t>(a.max_file_mb << 20);
  return run_folder(f);
}

// Everything a user can get wrong is checked before the run (issue 12):
// options, the scenario (parsed, with --model, within the limits), outputs.
Scenario read_checked_scenario(RunArgs& a) {
#ifndef SREH_WITH_RENDER
  if (!a.video.empty() || !a.frames.empty()) throw InputError("--video: built without rendering (SREH_WITH_RENDER=OFF)");
  if (!a.report.empty()) throw InputError("--report: built without rendering (SREH_WITH_RENDER=OFF)");
#endif
  check_size(a.size);
  if (a.camera != "default" && a.camera != "top") {
    throw InputError(fmt::format("--camera {}: expected default or top", a.camera));
  }
  a.limits.max_trace_bytes = a.max_trace_mb << 20;
  a.limits.max_file_bytes = static_cast<std::size_t>(a.max_file_mb << 20);
  Scenario scenario;
  try {
    scenario = parse_scenario_file(a.scenario, a.limits);
    apply_command_line_model(scenario, a.model);
    check_run_bound(scenario, a.limits);
  } catch (const ScenarioError& e) {
    throw InputError(e.what());
  }
  io::check_outputs({{"--trace", a.trace, io::OutputKind::File},
                     {"--save-nvm", a.save_nvm, io::OutputKind::File},
                     {"--junit", a.junit, io::OutputKind::File},
                     {"--master-log", a.master_log, io::OutputKind::File},
                     {"--video", a.video, io::OutputKind::File},
                     {"--frames", a.frames, io::OutputKind::EmptyFolder},
                     {"--report", a.report, io::OutputKind::Folder}},
                    inputs_of(a, scenario));
#ifdef SREH_WITH_RENDER
  if (!a.video.empty() && !container_for(a.video)) {
    throw InputError(fmt::format("--video {}: the extension must be .mp4, .webm or .gif", a.video));
  }
#endif
  return scenario;
}

// --trace and --master-log stream while the run goes (nothing that grows
// with run length stays in memory, issue 12).
void open_streams(const RunArgs& a, std::optional<TraceStream>& trace, std::optional<MasterLogStream>& master_log) {
  if (!a.trace.empty()) {
    for_option("--trace", a.trace, [&] { trace.emplace(a.trace, a.trace_every, a.limits.max_trace_bytes); });
  }
  if (!a.master_log.empty()) {
    for_option("--master-log", a.master_log, [&] { master_log.emplace(a.master_log); });
  }
}

// After the run: the streamed files committed, the memory image and JUnit written.
void commit_outputs(const RunArgs& a, const RunResult& result, double wall_s, std::optional<TraceStream>& trace,
                    std::optional<MasterLogStream>& master_log, JunitReport& junit) {
  try {
    if (trace) trace->commit();
    if (master_log) master_log->commit();
    write_nvm(a, result);
    if (!a.junit.empty()) {
      junit.end_case(result, wall_s);
      junit.write(a.junit);
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }
}

int run_command(RunArgs a) {
  std::error_code ec;
  if (std::filesystem::is_directory(a.scenario, ec)) return run_folder_command(a);
  if (!a.shard.empty()) {
    throw InputError(fmt::format("--shard {}: only with a folder of scenarios (run DIR --shard i/N); {} is a file",
                                 a.shard, a.scenario));
  }
  Scenario scenario = read_checked_scenario(a);

  RunResult result;
  std::optional<TraceStream> trace;
  std::optional<MasterLogStream> master_log;
  open_streams(a, trace, master_log);
  // Nothing that grows with run length stays in memory (issue 12): the
  // trace goes to --trace as it is made; checks, failures and moves to the
  // output's temporaries; with --report rows, checks and moves to the
  // report's as well.
  std::optional<RunOutput> output;
#ifdef SREH_WITH_RENDER
  std::optional<RunMedia> media;
#endif
  try {
    output.emplace(a.json);
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }
  double wall_s = 0; // the simulation's own wall time: what real_time_factor compares with
  JunitReport junit;
  try {
    Progress progress(isatty(STDERR_FILENO) != 0, a.quiet);
    progress.phase("simulating");
    RunOptions options;
    options.limits = a.limits;
    output->attach(options);
    if (!a.junit.empty()) junit.begin_case(a.scenario, scenario.name);
    if (trace) options.trace_sink = [&](const TraceRow& row) { trace->row(row); };
    options.on_cycle = [&](const Twin& twin) { progress.update(-1.0, twin.time_s()); };
    if (master_log) master_log->attach(options);
    if (!a.junit.empty()) junit.chain(options);
#ifdef SREH_WITH_RENDER
    if (!a.video.empty() || !a.frames.empty() || !a.report.empty()) {
      try {
        media.emplace(scenario, media_options(a));
      } catch (const std::runtime_error& e) {
        throw InputError(e.what());
      }
      media->attach(options);
    }
    result = timed_run(scenario, options, wall_s);
    if (media) {
      try {
        if (!a.video.empty() || !a.frames.empty()) progress.phase("rendering the video");
        media->render_video(result, [&progress](double fraction) { progress.update(fraction); });
      } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
      }
    }
#else
    result = timed_run(scenario, options, wall_s);
#endif
  } catch (const ScenarioError& e) {
    throw InputError(e.what());
  }
  commit_outputs(a, result, wall_s, trace, master_log, junit);
#ifdef SREH_WITH_RENDER
  if (media && !a.report.empty()) for_option("--report", a.report, [&] { media->write_report(result); });
#endif
  output->print(std::cout, result, wall_s);
  return result.passed ? 0 : 1;
}

} // namespace

SREH_REGISTER_COMMAND(10, [](CLI::App& app, int& exit_code) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* cmd = app.add_subcommand("run", "Simulate a scenario (or a folder of them) and check its expectations (exit 0 held, 1 failed, 2 bad input)");
  cmd->add_option("scenario", args->scenario,
                  "Scenario file (YAML, see scenarios/README.md), or a folder: every *.yaml in it, sorted by name, "
                  "one line each (exit 0 all held, 1 any failed, 2 bad input in any)")
      ->required();
  cmd->add_option("--trace", args->trace, "Write a CSV trace to this file, one row per IO-Link cycle (streamed to disk)");
  cmd->add_option("--master-log", args->master_log,
                  "Write what an IO-Link master sees, one row per master cycle: t_s,pd_out,pd_in,temperature_C "
                  "(hex process data; the temperature where the scenario polls index 112), what `calibrate` reads");
  cmd->add_option("--trace-every", args->trace_every, "Keep every Nth cycle in the trace, 1 .. 1000000")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  cmd->add_flag("--json", args->json,
                "Print one JSON object with the results on stdout (a folder: one object per file and line, JSON Lines)");
  cmd->add_option("--shard", args->shard,
                  "With a folder: run only block i of N of its files: i/N (rerun of one task of a Slurm array 1-N: "
                  "$SLURM_ARRAY_TASK_ID/N), auto (Slurm array FIRST-LAST[:STEP]: (SLURM_ARRAY_TASK_ID - "
                  "SLURM_ARRAY_TASK_MIN) / SLURM_ARRAY_TASK_STEP + 1 of SLURM_ARRAY_TASK_COUNT) or auto/N "
                  "(Kubernetes indexed Job: JOB_COMPLETION_INDEX + 1)");
  cmd->add_option("--video", args->video, "Render a video of the run: .mp4 (H.264), .webm (VP8) or .gif");
  cmd->add_option("--fps", args->fps, "Video frames per second, 1 .. 240")->check(CLI::Range(1, 240))->capture_default_str();
  cmd->add_option("--size", args->size, "Video size WIDTHxHEIGHT in pixels (even numbers, 16 .. 4096)")->capture_default_str();
  cmd->add_option("--slowmo", args->slowmo,
                  "Play the whole video this many times slower than simulated time, 0.01 .. 1000 [default: automatic: "
                  "one factor for every move, the shortest >= 2 s on screen (a move over 5x longer gets its own, "
                  "named in the banner); idle > 2 s sped up to 1 s]")
      ->check(CLI::Range(0.01, 1000.0));
  cmd->add_option("--frames", args->frames, "Also write PNG frames into this folder (new or empty)");
  cmd->add_option("--camera", args->camera, "Camera: default (fits module and load, 135 deg azimuth, 30 deg down) or top")
      ->capture_default_str();
  cmd->add_option("--report", args->report, "Write an HTML report folder (index.html, the video copied in) here");
  cmd->add_flag("--quiet", args->quiet, "No progress lines on stderr (they come for work over 2 s)");
  cmd->add_option("--junit", args->junit,
                  "Also write the result as JUnit XML for CI servers: one testcase per scenario (a folder: per file)");
  cmd->add_option("--model", args->model,
                  "Model card overrides (YAML, `sreh-twin model show` prints the format): the module's physical "
                  "constants, applied over the scenario's own `model:`");
  cmd->add_option("--save-nvm", args->save_nvm, "Save the device's non-volatile memory at the end to this file");
  // Limits (issue 12, scenarios/README.md "Limits"): exceeding one is exit 2.
  Limits& l = args->limits;
  cmd->add_option("--max-sim-s", l.max_sim_s, "Limit: simulated time of the run, s")
      ->capture_default_str()->check(CLI::Range(0.0, 1e9));
  cmd->add_option("--max-steps", l.max_steps, "Limit: executed steps (repeats unrolled)")->capture_default_str();
  cmd->add_option("--max-checks", l.max_checks, "Limit: recorded checks (repeats unrolled; streamed to temporary files)")->capture_default_str();
  cmd->add_option("--max-trace-mb", args->max_trace_mb, "Limit: size of the --trace file, MB")
      ->capture_default_str()->check(CLI::Range(uint64_t{1}, uint64_t{1} << 30));
  cmd->add_option("--max-file-mb", args->max_file_mb, "Limit: size of the scenario file, MB")
      ->capture_default_str()->check(CLI::Range(uint64_t{1}, uint64_t{1} << 20));
  cmd->add_option("--max-yaml-nodes", l.max_yaml_nodes, "Limit: YAML nodes once aliases are expanded")->capture_default_str();
  cmd->add_option("--max-yaml-depth", l.max_yaml_depth, "Limit: nesting depth of YAML lists / mappings")
      ->capture_default_str()->check(CLI::Range(1, 10000));
  cmd->callback([args, &exit_code] { exit_code = run_command(*args); });
});

} // namespace sreh::tools
