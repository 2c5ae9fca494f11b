// A run kept for its video (issue 16): the flange state and what the
// overlay shows, once per IO-Link cycle, so that the video can be rendered
// after the run with a time map built from where the motion actually was
// (slow motion per move, idle compressed: renders/time_map.hpp).
// About 230 bytes per cycle (FrameInfo 208 + qpos; ~115 kB per simulated
// second at 2 ms).
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
  std::size_t samples() const { return info_.size(); }
  double duration_s() const { return info_.empty() ? 0.0 : info_.back().row.t_s; }
  // Stretches where a trajectory runs or settles or the flange turns.
  std::vector<std::pair<double, double>> motion() const;

  // Renders the video: `options.time_map` if set; otherwise constant
  // `options.slowmo` when `fixed_slowmo`, else the automatic time map.
  // Frames between two cycles show the flange pose interpolated between
  // them (A-RENDERS-12). Throws like VideoRecorder.
  VideoSummary render(VideoOptions options, bool fixed_slowmo, const TimeScaleOptions& scale = {}) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<FrameInfo> info_;
};

} // namespace sreh
