#include "renders/time_map.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace sreh {

std::string TimeSegment::label() const {
  switch (kind) {
    case Kind::RealTime: return "real time";
    case Kind::SlowMotion:
      return previous_slowmo > 0 ? fmt::format("slow motion {:g}x (was {:g}x)", rate, previous_slowmo)
                                 : fmt::format("slow motion {:g}x", rate);
    case Kind::FastForward: return fmt::format("fast forward {:.0f}x (idle)", 1.0 / rate);
  }
  return "";
}

double nice_factor_up(double x) {
  if (!(x > 1.0)) return 1.0;
  const double mag = std::pow(10.0, std::floor(std::log10(x)));
  for (double f : {1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0}) {
    if (f * mag >= x * (1 - 1e-12)) return f * mag;
  }
  return 10 * mag;
}

void TimeMap::push(double t0, double t1, double rate, TimeSegment::Kind kind) {
  if (!(t1 > t0)) return;
  const double v0 = segments_.empty() ? 0.0 : segments_.back().v0_s + (segments_.back().t1_s - segments_.back().t0_s) * segments_.back().rate;
  if (!segments_.empty() && segments_.back().rate == rate && segments_.back().kind == kind) {
    segments_.back().t1_s = t1;
    return;
  }
  segments_.push_back({t0, t1, v0, rate, kind});
}

TimeMap TimeMap::constant(double slowmo, double duration_s) {
  if (!(slowmo > 0)) throw std::invalid_argument("slow motion factor must be positive");
  TimeMap m;
  m.duration_s_ = std::max(0.0, duration_s);
  const auto kind = slowmo > 1 ? TimeSegment::Kind::SlowMotion
                               : slowmo < 1 ? TimeSegment::Kind::FastForward : TimeSegment::Kind::RealTime;
  m.segments_.push_back({0.0, std::max(m.duration_s_, 1e-9), 0.0, slowmo, kind});
  return m;
}

TimeMap TimeMap::automatic(std::vector<std::pair<double, double>> motion, double duration_s, const TimeScaleOptions& o) {
  TimeMap m;
  m.duration_s_ = std::max(0.0, duration_s);
  const double T = m.duration_s_;
  // Stretches of motion, clipped to the run, sorted and merged.
  std::vector<std::pair<double, double>> runs;
  for (auto [a, b] : motion) {
    a = std::clamp(a, 0.0, T);
    b = std::clamp(b, 0.0, T);
    if (b < a) std::swap(a, b);
    runs.emplace_back(a, b);
  }
  std::sort(runs.begin(), runs.end());
  std::vector<std::pair<double, double>> merged;
  for (const auto& r : runs) {
    if (!merged.empty() && r.first <= merged.back().second + o.merge_gap_s) {
      merged.back().second = std::max(merged.back().second, r.second);
    } else {
      merged.push_back(r);
    }
  }
  // The factor each stretch would want on its own (min_move_video_s on
  // screen), then one factor for all: the largest, which every stretch
  // within max_factor_ratio of it shares; the rest likewise among
  // themselves (issue 39, A-RENDERS-19).
  std::vector<double> want; // unrounded: a long move wants less than 1
  for (const auto& [a, b] : merged) want.push_back(std::min(o.max_slowmo, o.min_move_video_s / std::max(b - a, 1e-6)));
  std::vector<double> factor(want.size(), 0.0);
  for (;;) {
    double top = 0;
    for (std::size_t i = 0; i < want.size(); ++i) {
      if (factor[i] == 0) top = std::max(top, want[i]);
    }
    if (top == 0) break;
    const double rate = std::min(o.max_slowmo, nice_factor_up(top));
    for (std::size_t i = 0; i < want.size(); ++i) {
      if (factor[i] == 0 && want[i] * std::max(1.0, o.max_factor_ratio) >= top * (1 - 1e-12)) factor[i] = rate;
    }
  }
  // Each stretch with its padding at its factor; gaps in between.
  struct Slow { double a, b, rate; };
  std::vector<Slow> slow;
  for (std::size_t i = 0; i < merged.size(); ++i) {
    const auto& [a, b] = merged[i];
    const double rate = factor[i];
    const double pad = o.pad_video_s / rate;
    double lo = std::max(0.0, a - pad), hi = std::min(T, b + pad);
    if (!slow.empty() && lo < slow.back().b) {
      // Padding overlaps the previous stretch: split the gap between them.
      const double mid = 0.5 * (slow.back().b + a);
      lo = std::max(mid, a - pad);
      slow.back().b = std::min(slow.back().b, lo);
    }
    slow.push_back({lo, hi, rate});
  }
  auto gap = [&](double t0, double t1) {
    if (!(t1 > t0)) return;
    if (t1 - t0 > o.idle_threshold_s) {
      m.push(t0, t1, o.idle_video_s / (t1 - t0), TimeSegment::Kind::FastForward);
    } else {
      m.push(t0, t1, 1.0, TimeSegment::Kind::RealTime);
    }
  };
  double t = 0;
  for (const Slow& s : slow) {
    gap(t, s.a);
    m.push(std::max(t, s.a), s.b, s.rate, s.rate > 1 ? TimeSegment::Kind::SlowMotion : TimeSegment::Kind::RealTime);
    t = std::max(t, s.b);
  }
  gap(t, T);
  double last_slowmo = 0;
  for (TimeSegment& seg : m.segments_) {
    if (seg.kind != TimeSegment::Kind::SlowMotion) continue;
    if (last_slowmo > 0 && seg.rate != last_slowmo) seg.previous_slowmo = last_slowmo;
    last_slowmo = seg.rate;
  }
  if (m.segments_.empty()) m.segments_.push_back({0.0, std::max(T, 1e-9), 0.0, 1.0, TimeSegment::Kind::RealTime});
  return m;
}

std::vector<double> TimeMap::slowmo_factors() const {
  std::vector<double> out;
  for (const TimeSegment& seg : segments_) {
    if (seg.kind == TimeSegment::Kind::SlowMotion && std::find(out.begin(), out.end(), seg.rate) == out.end()) out.push_back(seg.rate);
  }
  return out;
}

std::string TimeMap::describe(const TimeScaleOptions& o) const {
  const std::vector<double> f = slowmo_factors();
  bool idle = false;
  for (const TimeSegment& seg : segments_) idle = idle || seg.kind == TimeSegment::Kind::FastForward;
  std::string out;
  if (f.empty()) {
    out = "real time";
  } else if (f.size() == 1) {
    out = fmt::format("slow motion {:g}x for every move", f[0]);
  } else {
    std::string list;
    for (std::size_t i = 0; i < f.size(); ++i) list += fmt::format("{}{:g}x", i == 0 ? "" : i + 1 == f.size() ? " and " : ", ", f[i]);
    out = fmt::format("slow motion {} (moves differ more than {:g}x in length)", list, o.max_factor_ratio);
  }
  return idle ? out + ", idle sped up" : out;
}

const TimeSegment& TimeMap::segment_at(double t_s) const {
  auto it = std::upper_bound(segments_.begin(), segments_.end(), t_s, [](double t, const TimeSegment& s) { return t < s.t1_s; });
  if (it == segments_.end()) return segments_.back();
  return *it;
}

double TimeMap::video_time(double t_s) const {
  const TimeSegment& s = segment_at(t_s);
  return s.v0_s + (std::min(t_s, s.t1_s) - s.t0_s) * s.rate;
}

double TimeMap::video_duration_s() const { return video_time(duration_s_); }

double TimeMap::sim_time(double video_s) const {
  auto it = std::upper_bound(segments_.begin(), segments_.end(), video_s,
                             [](double v, const TimeSegment& s) { return v < s.v0_s + (s.t1_s - s.t0_s) * s.rate; });
  const TimeSegment& s = it == segments_.end() ? segments_.back() : *it;
  return s.t0_s + (video_s - s.v0_s) / s.rate;
}

} // namespace sreh
