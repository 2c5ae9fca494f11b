// Video time as a function of simulated time (issue 16): every move slowed
// down to a watchable on-screen duration, long idle stretches compressed,
// real time in between (docs/assumptions/renders.md A-RENDERS-12). Pure: no
// MuJoCo, no files; the recorder asks it when each frame is due.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace sreh {

// One stretch of simulated time played at one rate.
struct TimeSegment {
  enum class Kind : uint8_t { RealTime, SlowMotion, FastForward };
  double t0_s = 0;     // simulated
  double t1_s = 0;
  double v0_s = 0;     // video time at t0_s
  double rate = 1;     // video seconds per simulated second (> 1: slow motion)
  Kind kind = Kind::RealTime;
  // Slow motion after slow motion at another factor: that factor (issue 39:
  // the banner names the change); else 0.
  double previous_slowmo = 0;
  // "real time", "slow motion 20x", "slow motion 40x (was 20x)", "fast forward 37x (idle)"
  std::string label() const;
};

struct TimeScaleOptions {
  double min_move_video_s = 2.0;   // each stretch of motion lasts at least this long on screen
  double max_slowmo = 100.0;       // never slower than this
  double pad_video_s = 0.3;        // shown at the move's rate before and after it
  double idle_threshold_s = 2.0;   // idle stretches longer than this (simulated) ...
  double idle_video_s = 1.0;       // ... play in this many video seconds
  double merge_gap_s = 0.0;        // motion separated by at most this is one stretch
  // One slow-motion factor for every move (issue 39), so that moves compare
  // on screen: the one that gives the shortest move min_move_video_s; moves
  // that would get a factor more than this many times smaller on their own
  // (a move this much longer) get their own factor, which the banner names
  // (docs/assumptions/renders.md A-RENDERS-20).
  double max_factor_ratio = 5.0;
  double end_hold_video_s = 0.5;   // the final state stays this long (RunRecording)
};

class TimeMap {
 public:
  // The whole run [0, duration_s] at one slow-motion factor (--slowmo).
  static TimeMap constant(double slowmo, double duration_s);
  // Automatic scaling from the stretches of motion [start, end] (simulated
  // seconds, any order, may overlap).
  static TimeMap automatic(std::vector<std::pair<double, double>> motion, double duration_s,
                           const TimeScaleOptions& options = {});

  double duration_s() const { return duration_s_; }
  double video_duration_s() const;
  double video_time(double t_s) const;
  double sim_time(double video_s) const;
  const TimeSegment& segment_at(double t_s) const;
  const std::vector<TimeSegment>& segments() const { return segments_; }
  // The slow-motion factors the moves play at, in order of first use.
  std::vector<double> slowmo_factors() const;
  // How the video plays the run, for the title card: "slow motion 20x for
  // every move, idle sped up" / "slow motion 40x and 8x (moves differ
  // more than 5x in length), ..." / "real time".
  std::string describe(const TimeScaleOptions& options = {}) const;

 private:
  void push(double t0, double t1, double rate, TimeSegment::Kind kind);
  std::vector<TimeSegment> segments_;
  double duration_s_ = 0;
};

// The smallest of 1, 1.5, 2, 3, 4, 5, 6, 8 x 10^n that is >= x (x >= 1).
double nice_factor_up(double x);

} // namespace sreh
