// The video and the HTML report of one scenario run (issue 7, 16, 29, 39),
// for every front end: `sreh-twin run --video/--frames/--report` and
// Python's run_scenario(video=..., report=...). Attached to the run's
// options before it starts, it records what it needs as the run goes
// (memory flat with run length, issue 12) and writes its files after it.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renders/run_recording.hpp"
#include "renders/video.hpp"
#include "renders/video_title.hpp"
#include "scenarios/runner.hpp"
#include "scenarios/scenario.hpp"

namespace sreh {

struct RunMediaOptions {
  // Set (a path and/or a frames folder): render a video. With fixed_slowmo
  // the whole run plays at video->slowmo; otherwise the automatic time map.
  std::optional<VideoOptions> video;
  bool fixed_slowmo = false;
  std::string report_dir;     // non-empty: write the report folder here
  std::string command_line;   // shown in the report
  std::string version;
};

// What a video of the run shows on its closing card (issue 39): the verdict,
// the checks that failed (the first few of `failures`, then how many more
// of failures_total) and the state the run ended in.
TitleCard make_closing_card(const RunResult& result, const std::vector<std::string>& failures, std::size_t failures_total);

// The load's own name for the title card (issue 39): a load file's `name:`
// (with the file's name), an MJCF file's name, an inline assembly's parts,
// or describe_load() for the simple shapes; never "file.yaml:8:5".
std::string load_title(const LoadSpec& load, const std::string& scenario_file);

class RunMedia {
 public:
  RunMedia(const Scenario& scenario, RunMediaOptions options);
  ~RunMedia();
  RunMedia(const RunMedia&) = delete;
  RunMedia& operator=(const RunMedia&) = delete;

  // Chains onto the options' sinks and callbacks (those already set still run first).
  void attach(RunOptions& options);
  // After the run: renders the video, if asked for (progress: the share
  // rendered, 0..1). Throws std::invalid_argument for options the renderer
  // refuses, std::runtime_error when it cannot render or write.
  void render_video(const RunResult& result, const std::function<void(double)>& progress = {});
  // Then the report folder, if asked for (the video copied in). Throws
  // std::runtime_error when it cannot be written.
  void write_report(const RunResult& result);
  // The video's summary once finish() rendered one.

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace sreh
