#include "renders/run_recording.hpp"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <ostream>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>

#include "io/spool.hpp"

namespace sreh {

namespace {
constexpr double kTurningDps = 1.0; // the flange counts as turning above this speed

// One cycle in the spool, followed by the model's nq joint positions.
struct Sample {
  TraceRow row;
  double ghost_joint_rad = 0;
  uint32_t step = 0;    // index into Impl::steps
  uint32_t caption = 0; // index into Impl::steps too
  bool has_ghost = false;
};
static_assert(std::is_trivially_copyable_v<Sample>);
} // namespace

struct RunRecording::Impl {
  mjModel* model = nullptr;
  std::vector<double> mocap;  // mocap_pos + mocap_quat of the first sample
  io::Spool spool;            // Sample + nq doubles per cycle
  std::size_t record_bytes = 0;
  std::size_t samples = 0;
  double first_t_s = 0, last_t_s = 0;
  // Step labels and captions are few (one per scenario step): stored once each.
  std::vector<std::string> steps;
  std::unordered_map<std::string, uint32_t> step_ids;
  std::vector<std::pair<double, double>> motion;
  bool last_active = false;
  ~Impl() {
    if (model) mj_deleteModel(model);
  }
};

// The samples read back in time order, a chunk at a time; the sample before
// the one asked for stays readable (rendering blends j and j + 1).
class RunRecording::Reader {
 public:
  explicit Reader(Impl& s) : s_(s), nq_(static_cast<std::size_t>(s.model->nq)) {}
  // Sample i and its joint positions (valid until the next call).
  const Sample& sample(std::size_t i, const double** qpos) {
    if (i < first_ || i >= first_ + count_) load(i > 0 ? i - 1 : 0);
    const char* at = buffer_.data() + (i - first_) * s_.record_bytes;
    std::memcpy(&sample_, at, sizeof sample_);
    qpos_.resize(nq_);
    std::memcpy(qpos_.data(), at + sizeof(Sample), nq_ * sizeof(double));
    if (qpos) *qpos = qpos_.data();
    return sample_;
  }
  FrameInfo frame(std::size_t i, const double** qpos) {
    const Sample& smp = sample(i, qpos);
    FrameInfo f;
    f.row = smp.row;
    if (smp.has_ghost) f.ghost_joint_rad = smp.ghost_joint_rad;
    f.step = s_.steps[smp.step];
    f.caption = s_.steps[smp.caption];
    return f;
  }

 private:
  void load(std::size_t from) {
    constexpr std::size_t kChunk = 4096;
    first_ = from;
    count_ = std::min(kChunk, s_.samples - from);
    buffer_.resize(count_ * s_.record_bytes);
    s_.spool.read_at(static_cast<unsigned long long>(from) * s_.record_bytes, buffer_.data(), buffer_.size());
  }
  Impl& s_;
  std::size_t nq_;
  std::size_t first_ = 0, count_ = 0;
  std::vector<char> buffer_;
  Sample sample_;
  std::vector<double> qpos_;
};

RunRecording::RunRecording(const mjModel* m) : impl_(std::make_unique<Impl>()) {
  impl_->model = mj_copyModel(nullptr, m);
  if (!impl_->model) throw std::runtime_error("video: cannot copy the MuJoCo model");
  impl_->record_bytes = sizeof(Sample) + static_cast<std::size_t>(impl_->model->nq) * sizeof(double);
}

RunRecording::~RunRecording() = default;

void RunRecording::add(const mjData* d, const FrameInfo& info) {
  Impl& s = *impl_;
  const mjModel* m = s.model;
  const TraceRow& r = info.row;
  if (s.samples == 0) {
    s.mocap.assign(d->mocap_pos, d->mocap_pos + 3 * m->nmocap);
    s.mocap.insert(s.mocap.end(), d->mocap_quat, d->mocap_quat + 4 * m->nmocap);
    s.first_t_s = r.t_s;
  }
  Sample smp;
  smp.row = r;
  smp.has_ghost = info.ghost_joint_rad.has_value();
  smp.ghost_joint_rad = info.ghost_joint_rad.value_or(0.0);
  auto id_of = [&s](const std::string& text) {
    const auto [it, added] = s.step_ids.try_emplace(text, static_cast<uint32_t>(s.steps.size()));
    if (added) s.steps.push_back(text);
    return it->second;
  };
  smp.step = id_of(info.step);
  smp.caption = id_of(info.caption);
  s.spool.stream().write(reinterpret_cast<const char*>(&smp), sizeof smp);
  s.spool.stream().write(reinterpret_cast<const char*>(d->qpos), static_cast<std::streamsize>(m->nq * sizeof(double)));
  // A cycle's sample closes the cycle that led to it: motion from the one before.
  const bool active = r.moving || r.settling || std::abs(r.velocity_dps) > kTurningDps;
  if (active) {
    if (s.last_active) s.motion.back().second = r.t_s;
    else s.motion.emplace_back(s.samples > 0 ? s.last_t_s : r.t_s, r.t_s);
  }
  s.last_active = active;
  s.last_t_s = r.t_s;
  ++s.samples;
}

std::size_t RunRecording::samples() const { return impl_->samples; }
double RunRecording::duration_s() const { return impl_->samples == 0 ? 0.0 : impl_->last_t_s; }
const std::vector<std::pair<double, double>>& RunRecording::motion() const { return impl_->motion; }

VideoSummary RunRecording::render(VideoOptions o, bool fixed_slowmo, const TimeScaleOptions& scale) const {
  Impl& s = *impl_;
  if (s.samples == 0) throw std::runtime_error("video: no frame was recorded");
  const double t_end = duration_s();
  if (!o.time_map) {
    o.time_map = fixed_slowmo ? TimeMap::constant(o.slowmo, t_end) : TimeMap::automatic(motion(), t_end, scale);
  }
  const mjModel* m = s.model;
  VideoRecorder rec(m, o);
  mjData* d = mj_makeData(m);
  if (!d) throw std::runtime_error("video: cannot allocate MuJoCo data");
  VideoSummary summary;
  Reader samples(s);
  std::vector<double> q0(static_cast<std::size_t>(m->nq)), q1(q0.size());
  auto t_of = [&](std::size_t i) { return samples.sample(i, nullptr).row.t_s; };
  try {
    std::copy(s.mocap.begin(), s.mocap.begin() + 3 * m->nmocap, d->mocap_pos);
    std::copy(s.mocap.begin() + 3 * m->nmocap, s.mocap.end(), d->mocap_quat);
    std::size_t j = 0;
    for (uint64_t k = 0;; ++k) {
      const double t = rec.frame_time_s(k);
      if (t > t_end + 1e-9) break;
      while (j + 1 < s.samples && t_of(j + 1) <= t + 1e-9) ++j;
      // Between samples j and j+1: the pose and the continuous numbers blended.
      const bool between = j + 1 < s.samples && t > t_of(j) + 1e-9 && t >= s.first_t_s;
      const double* q = nullptr;
      FrameInfo b;
      if (between) {
        b = samples.frame(j + 1, &q);
        std::copy(q, q + m->nq, q1.begin());
      }
      FrameInfo f = samples.frame(j, &q);
      std::copy(q, q + m->nq, q0.begin());
      if (!between) q1 = q0;
      const double w = between ? (t - f.row.t_s) / (b.row.t_s - f.row.t_s) : 0.0;
      for (int i = 0; i < m->nq; ++i) d->qpos[i] = q0[i] + w * (q1[i] - q0[i]);
      mj_kinematics(m, d);
      mj_comPos(m, d);
      mj_camlight(m, d);
      if (between) {
        auto blend = [w](double a0, double a1) { return a0 + w * (a1 - a0); };
        f.row.position_deg = blend(f.row.position_deg, b.row.position_deg);
        f.row.setpoint_deg = blend(f.row.setpoint_deg, b.row.setpoint_deg);
        f.row.tracking_error_deg = blend(f.row.tracking_error_deg, b.row.tracking_error_deg);
        if (f.ghost_joint_rad && b.ghost_joint_rad) f.ghost_joint_rad = blend(*f.ghost_joint_rad, *b.ghost_joint_rad);
      }
      f.row.t_s = std::max(t, s.first_t_s);
      rec.add_frame(m, d, f);
      if (o.progress && t_end > 0) o.progress(t / t_end);
    }
    // The end state stays on screen a moment (A-RENDERS-12).
    FrameInfo last = samples.frame(s.samples - 1, nullptr);
    const double tail_s = std::max(0.0, scale.end_hold_video_s);
    rec.hold(m, d, last, static_cast<uint64_t>(std::llround(tail_s * o.fps)));
    rec.close(m, d, last); // the closing card, when given (issue 39)
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
