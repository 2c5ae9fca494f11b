// A run kept for its video (issue 16): the flange state and what the
// overlay shows, once per IO-Link cycle, so that the video can be rendered
// after the run with a time map built from where the motion actually was
// (slow motion per move, idle compressed: renders/time_map.hpp).
// The samples go to a private temporary file (io::Spool), about 200 bytes
// per cycle, and are read back in order while rendering: memory does not
// grow with run length (issue 12). Held in memory: the stretches of motion
// and the distinct step labels.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "renders/video.hpp"

struct mjModel_;
struct mjData_;

namespace sreh {

struct VideoSummary {
  uint64_t frames = 0;
  double video_s = 0;
  double max_slowmo = 1;       // largest slow-motion factor used
  std::vector<TimeSegment> segments;
};

class RunRecording {
 public:
  // Copies the model: the twin that owns `m` may be gone when rendering.
  explicit RunRecording(const mjModel_* m);
  ~RunRecording();
  RunRecording(const RunRecording&) = delete;
  RunRecording& operator=(const RunRecording&) = delete;

  // One sample per cycle, in time order. `d` is only read (qpos, mocap).
  // The row's moving / settling / velocity mark where the motion is.
  void add(const mjData_* d, const FrameInfo& info);
  std::size_t samples() const;
  double duration_s() const; // the last sample's time
  // Stretches where a trajectory runs or settles or the flange turns.
  const std::vector<std::pair<double, double>>& motion() const;

  // Renders the video: `options.time_map` if set; otherwise constant
  // `options.slowmo` when `fixed_slowmo`, else the automatic time map.
  // Frames between two cycles show the flange pose interpolated between
  // them (A-RENDERS-12). Throws like VideoRecorder.
  VideoSummary render(VideoOptions options, bool fixed_slowmo, const TimeScaleOptions& scale = {}) const;

 private:
  struct Impl;
  class Reader;
  std::unique_ptr<Impl> impl_;
};

} // namespace sreh
