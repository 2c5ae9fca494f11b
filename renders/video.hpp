// Video of a twin run (issue 7, 16): the caller hands over MuJoCo states in
// simulated-time order; frame k is due at the simulated time the time map
// gives for video time k / fps (constant slow motion, or automatic scaling:
// renders/time_map.hpp), rendered off-screen and encoded by ffmpeg to the
// container the file's extension names (.mp4, .webm, .gif) and/or written
// as PNG frames. The caller's thread only renders;
// a writer thread feeds ffmpeg and libpng (docs/performance-renders.md).
// Output appears atomically: F.tmp (and DIR.tmp) renamed on finish().
#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "renders/ffmpeg_encoder.hpp"
#include "renders/offscreen.hpp"
#include "renders/time_map.hpp"
#include "twin/trace.hpp"

struct mjModel_;
struct mjData_;

namespace sreh {

struct VideoOptions {
  std::filesystem::path path;       // .mp4, .webm or .gif to write; empty: no video
  double fps = 30.0;
  int width_px = 1280;              // even
  int height_px = 720;              // even
  double slowmo = 1.0;              // video plays this many times slower than simulated time ...
  std::optional<TimeMap> time_map;  // ... unless a time map is given
  CameraSpec camera;
  std::filesystem::path frames_dir; // non-empty: PNG frames frame_000000.png ... here, and
                                    // text.tsv: the words each frame shows and where (kTextLogHeader)
  // Quality/speed (A-RENDERS-3, A-RENDERS-5).
  int msaa_samples = 4;
  bool shadows = false;
  int shadow_size = 2048;
  bool reflections = false;
  std::string x264_preset = "veryfast";
  int crf = 20;
  bool threaded = true;             // false: render and write on the caller's thread (the reference loop)
  bool redraw_changed_only = true;  // RenderOptions::redraw_changed_only (issue 31, A-RENDERS-18)
  bool overlay = true;
  // Set: this card is shown for title_s before the run's first frame
  // (issue 29); run frame k is then video frame title_frames() + k.
  std::optional<TitleCard> title;
  double title_s = 1.5;
  // Set: this card closes the video for closing_s after the run's last
  // frame (issue 39: the verdict, the failed checks, the final state).
  std::optional<TitleCard> closing;
  double closing_s = 3.0;
  // Called as frames are made with the share of the run rendered (0..1):
  // the CLI's progress line (issue 29). Empty: nothing.
  std::function<void(double)> progress;
};

// What the frame shows besides the MuJoCo state: the cycle's trace row as
// the twin recorded it (time, state, positions, codes, LED band, and the
// process data out whose target and parameter set the overlay shows), plus
// what only a frame has.
struct FrameInfo {
  TraceRow row;
  // Flange joint angle of the planned setpoint (qpos sense, rad). Unset:
  // the flange joint angle + (setpoint - position), factory direction
  // (A-RENDERS-7).
  std::optional<double> ghost_joint_rad;
  std::string step;                  // "4 wait_until"; empty: not shown
  std::string caption;               // the scenario's `comment:` in force; empty: none
};

// The text log's columns (issue 39): one row per text per run of identical
// frames, frames first..last, pixels from the top-left corner.
inline constexpr const char* kTextLogHeader = "first_frame\tlast_frame\tkind\tx\ty\twidth\theight\ttext";

class VideoRecorder {
 public:
  // Throws std::invalid_argument on bad options (nothing to write, odd size,
  // non-positive fps or slowmo, frames_dir not empty), std::runtime_error
  // if the renderer or ffmpeg cannot start.
  VideoRecorder(const mjModel_* m, const VideoOptions& options);
  ~VideoRecorder(); // without finish(): stops, leaves no output behind
  VideoRecorder(const VideoRecorder&) = delete;
  VideoRecorder& operator=(const VideoRecorder&) = delete;

  // True when the next frame is due: t_s >= frame_time_s(next) (1 ns slack
  // for the caller's cycles * cycle_s time).
  bool wants_frame(double t_s) const;
  // Renders the state once and emits every frame due up to info.t_s (more
  // than one when frames are denser than the caller's cycles). `d` is only
  // read (e.g. twin.plant().data()). Rethrows a writer-thread failure.
  void add_frame(const mjModel_* m, const mjData_* d, const FrameInfo& info);
  // Renders the state once and emits it as the next `count` frames,
  // whatever their due time (a still at the end of a run).
  void hold(const mjModel_* m, const mjData_* d, const FrameInfo& info, uint64_t count);
  // The closing card over the state of `d`, as the next round(closing_s * fps)
  // frames (nothing without options.closing).
  void close(const mjModel_* m, const mjData_* d, const FrameInfo& info);
  // Flushes, waits for ffmpeg, renames F.tmp -> F and DIR.tmp -> DIR.
  // Throws std::runtime_error (and removes the partial output) on failure.
  void finish();

  uint64_t frames_emitted() const; // video frames so far, the title card's included
  uint64_t title_frames() const;   // round(title_s * fps) with a title card, else 0
  // Simulated time at which run frame k is due (video frame title_frames() + k).
  double frame_time_s(uint64_t k) const;
  const TimeMap* time_map() const;       // null: constant slowmo

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The overlay lines a frame shows (also used by tests and the report).
std::vector<std::pair<std::string, std::string>> overlay_lines(const FrameInfo& info);

} // namespace sreh
