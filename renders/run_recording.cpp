#include "renders/run_recording.hpp"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sreh {

namespace {
constexpr double kTurningDps = 1.0; // the flange counts as turning above this speed
}

struct RunRecording::Impl {
  mjModel* model = nullptr;
  std::vector<double> mocap;  // mocap_pos + mocap_quat of the first sample
  std::vector<double> qpos;   // nq per sample
  std::vector<uint8_t> active;
  ~Impl() {
    if (model) mj_deleteModel(model);
  }
};

RunRecording::RunRecording(const mjModel* m) : impl_(std::make_unique<Impl>()) {
  impl_->model = mj_copyModel(nullptr, m);
  if (!impl_->model) throw std::runtime_error("video: cannot copy the MuJoCo model");
}

RunRecording::~RunRecording() = default;

void RunRecording::add(const mjData* d, const FrameInfo& info) {
  Impl& s = *impl_;
  const mjModel* m = s.model;
  if (info_.empty()) {
    s.mocap.assign(d->mocap_pos, d->mocap_pos + 3 * m->nmocap);
    s.mocap.insert(s.mocap.end(), d->mocap_quat, d->mocap_quat + 4 * m->nmocap);
  }
  s.qpos.insert(s.qpos.end(), d->qpos, d->qpos + m->nq);
  const TraceRow& r = info.row;
  s.active.push_back(r.moving || r.settling || std::abs(r.velocity_dps) > kTurningDps ? 1 : 0);
  info_.push_back(info);
}

std::vector<std::pair<double, double>> RunRecording::motion() const {
  std::vector<std::pair<double, double>> runs;
  const auto& a = impl_->active;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!a[i]) continue;
    // A cycle's sample closes the cycle that led to it: motion from the one before.
    const double t0 = i > 0 ? info_[i - 1].row.t_s : info_[i].row.t_s;
    if (!runs.empty() && i > 0 && a[i - 1]) {
      runs.back().second = info_[i].row.t_s;
    } else {
      runs.emplace_back(t0, info_[i].row.t_s);
    }
  }
  return runs;
}

VideoSummary RunRecording::render(VideoOptions o, bool fixed_slowmo, const TimeScaleOptions& scale) const {
  const Impl& s = *impl_;
  if (info_.empty()) throw std::runtime_error("video: no frame was recorded");
  const double t_end = duration_s();
  if (!o.time_map) {
    o.time_map = fixed_slowmo ? TimeMap::constant(o.slowmo, t_end) : TimeMap::automatic(motion(), t_end, scale);
  }
  const mjModel* m = s.model;
  VideoRecorder rec(m, o);
  mjData* d = mj_makeData(m);
  if (!d) throw std::runtime_error("video: cannot allocate MuJoCo data");
  VideoSummary summary;
  try {
    std::copy(s.mocap.begin(), s.mocap.begin() + 3 * m->nmocap, d->mocap_pos);
    std::copy(s.mocap.begin() + 3 * m->nmocap, s.mocap.end(), d->mocap_quat);
    std::size_t j = 0;
    for (uint64_t k = 0;; ++k) {
      const double t = rec.frame_time_s(k);
      if (t > t_end + 1e-9) break;
      while (j + 1 < info_.size() && info_[j + 1].row.t_s <= t + 1e-9) ++j;
      // Between samples j and j+1: the pose and the continuous numbers blended.
      const bool between = j + 1 < info_.size() && t > info_[j].row.t_s + 1e-9 && t >= info_.front().row.t_s;
      const double w = between ? (t - info_[j].row.t_s) / (info_[j + 1].row.t_s - info_[j].row.t_s) : 0.0;
      const double* q0 = s.qpos.data() + j * static_cast<std::size_t>(m->nq);
      const double* q1 = between ? q0 + m->nq : q0;
      for (int i = 0; i < m->nq; ++i) d->qpos[i] = q0[i] + w * (q1[i] - q0[i]);
      mj_kinematics(m, d);
      mj_comPos(m, d);
      mj_camlight(m, d);
      FrameInfo f = info_[j];
      if (between) {
        const FrameInfo& b = info_[j + 1];
        auto blend = [w](double a0, double a1) { return a0 + w * (a1 - a0); };
        f.row.position_deg = blend(f.row.position_deg, b.row.position_deg);
        f.row.setpoint_deg = blend(f.row.setpoint_deg, b.row.setpoint_deg);
        f.row.tracking_error_deg = blend(f.row.tracking_error_deg, b.row.tracking_error_deg);
        if (f.ghost_joint_rad && b.ghost_joint_rad) f.ghost_joint_rad = blend(*f.ghost_joint_rad, *b.ghost_joint_rad);
      }
      f.row.t_s = std::max(t, info_.front().row.t_s);
      rec.add_frame(m, d, f);
    }
    // The end state stays on screen a moment (A-RENDERS-12).
    FrameInfo last = info_.back();
    const double tail_s = std::max(0.0, scale.end_hold_video_s);
    rec.hold(m, d, last, static_cast<uint64_t>(std::llround(tail_s * o.fps)));
    rec.finish();
  } catch (...) {
    mj_deleteData(d);
    throw;
  }
  mj_deleteData(d);
  summary.frames = rec.frames_emitted();
  summary.video_s = static_cast<double>(summary.frames) / o.fps;
  summary.segments = o.time_map->segments();
  for (const TimeSegment& seg : summary.segments) summary.max_slowmo = std::max(summary.max_slowmo, seg.rate);
  return summary;
}

} // namespace sreh
