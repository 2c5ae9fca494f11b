#include "renders/video.hpp"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <exception>
#include <fstream>
#include <memory>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "device_logic/units.hpp"
#include "io/atomic_file.hpp"
#include "renders/ffmpeg_encoder.hpp"
#include "renders/png_writer.hpp"

namespace sreh {

namespace fs = std::filesystem;

// Short labels and values so that the panel stays under a quarter of a
// 640x360 frame (issue 29); the time scale is the banner's, not a row; the
// step spans both columns (empty label).
std::vector<std::pair<std::string, std::string>> overlay_lines(const FrameInfo& f) {
  auto code = [](uint8_t c) { return c == 0 ? std::string("none") : fmt::format("0x{:02X}", c); };
  const TraceRow& r = f.row;
  const ProcessDataOut out = decode_out(r.pd_out);
  std::vector<std::pair<std::string, std::string>> lines;
  lines.emplace_back("t", fmt::format("{:.4f} s", r.t_s));
  if (!f.step.empty()) lines.emplace_back("", "step " + f.step);
  lines.emplace_back("state", std::string(state_name(r.state)));
  lines.emplace_back("target", fmt::format("{:.2f} deg", wire_counts_to_deg(out.target_raw)));
  lines.emplace_back("set", fmt::format("{}", out.parameter_set));
  lines.emplace_back("setpoint", fmt::format("{:.2f} deg", r.setpoint_deg));
  lines.emplace_back("actual", fmt::format("{:.2f} deg", r.position_deg));
  lines.emplace_back("tracking", fmt::format("{:+.3f} deg", r.tracking_error_deg));
  lines.emplace_back("err/warn", code(r.error_code) + "/" + code(r.warning_code));
  lines.emplace_back("LED", std::string(led_name(r.led)));
  return lines;
}

namespace {

struct Job {
  std::size_t buffer = 0;
  uint64_t first_frame = 0;
  uint64_t count = 0;
};

} // namespace

struct VideoRecorder::Impl {
  VideoOptions options;
  double frame_rate_sim = 0; // frames per simulated second
  std::unique_ptr<OffscreenRenderer> renderer;
  std::unique_ptr<FfmpegEncoder> encoder;
  std::unique_ptr<io::AtomicFile> video_file; // ffmpeg writes its temporary
  std::unique_ptr<io::AtomicDir> frames_out;
  fs::path frames_tmp;
  std::ofstream text_log; // frames_tmp / text.tsv
  int flange_qpos = -1;
  uint64_t next_frame = 0;    // of the run: the title card's frames come before
  uint64_t title_frames = 0;
  bool title_done = false;
  bool finished = false;

  // Writer thread: buffers cycle free -> rendered (jobs) -> free.
  std::vector<std::vector<uint8_t>> buffers;
  std::deque<std::size_t> free_buffers;
  std::deque<Job> jobs;
  std::mutex mutex;
  std::condition_variable cv;
  bool closing = false;
  std::exception_ptr error;
  std::thread writer;

  void emit(const Job& job) {
    const std::vector<uint8_t>& rgb = buffers[job.buffer];
    for (uint64_t i = 0; i < job.count; ++i) {
      if (encoder) encoder->write_frame(rgb.data());
      if (!frames_tmp.empty()) {
        write_png(frames_tmp / fmt::format("frame_{:06d}.png", job.first_frame + i), rgb.data(), options.width_px,
                  options.height_px, true);
      }
    }
  }

  void writer_loop() {
    for (;;) {
      Job job;
      {
        std::unique_lock lock(mutex);
        cv.wait(lock, [&] { return closing || !jobs.empty(); });
        if (jobs.empty()) return;
        job = jobs.front();
        jobs.pop_front();
      }
      try {
        emit(job);
      } catch (...) {
        std::lock_guard lock(mutex);
        error = std::current_exception();
        free_buffers.push_back(job.buffer);
        cv.notify_all();
        return;
      }
      std::lock_guard lock(mutex);
      free_buffers.push_back(job.buffer);
      cv.notify_all();
    }
  }

  // Renders one image and hands it to the writer as frames first ..
  // first + count - 1 of the video.
  void queue(const mjModel* m, const mjData* d, const SceneState& scene, uint64_t first, uint64_t count) {
    if (count == 0) return;
    std::size_t buffer = 0;
    {
      std::unique_lock lock(mutex);
      cv.wait(lock, [&] { return error || !free_buffers.empty(); });
      if (error) std::rethrow_exception(error);
      buffer = free_buffers.front();
      free_buffers.pop_front();
    }
    renderer->render_into(m, d, scene, buffers[buffer].data(), false);
    if (text_log.is_open()) {
      for (const DrawnText& t : renderer->drawn_text()) {
        text_log << first << '\t' << first + count - 1 << '\t' << t.kind << '\t' << t.x << '\t' << t.y << '\t' << t.width
                 << '\t' << t.height << '\t' << t.text << '\n';
      }
      if (!text_log) throw std::runtime_error("video: cannot write " + (frames_tmp / "text.tsv").string());
    }
    const Job job{buffer, first, count};
    if (!options.threaded) {
      emit(job);
      free_buffers.push_back(buffer);
      return;
    }
    {
      std::lock_guard lock(mutex);
      jobs.push_back(job);
    }
    cv.notify_all();
  }

  void stop_writer() {
    if (!writer.joinable()) return;
    {
      std::lock_guard lock(mutex);
      closing = true;
    }
    cv.notify_all();
    writer.join();
  }

  void discard_output() {
    encoder.reset();
    if (text_log.is_open()) text_log.close();
    video_file.reset(); // removes the temporaries
    frames_out.reset();
  }
};

VideoRecorder::VideoRecorder(const mjModel* m, const VideoOptions& o) : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  if (o.path.empty() && o.frames_dir.empty()) throw std::invalid_argument("video: neither a video file nor a frames directory given");
  if (!(o.fps > 0) || !(o.slowmo > 0)) throw std::invalid_argument("video: fps and slow motion factor must be positive");
  if (o.width_px % 2 || o.height_px % 2 || o.width_px < 16 || o.height_px < 16) {
    throw std::invalid_argument(fmt::format("video: size {}x{} must be even and at least 16x16", o.width_px, o.height_px));
  }
  auto check_parent = [](const fs::path& p) {
    const fs::path parent = fs::absolute(p).parent_path();
    if (!fs::is_directory(parent)) throw std::invalid_argument("video: directory " + parent.string() + " does not exist");
  };
  if (o.title && !(o.title_s >= 0)) throw std::invalid_argument("video: the title card's duration must not be negative");
  s.options = o;
  s.frame_rate_sim = o.fps * o.slowmo;
  if (o.title) s.title_frames = static_cast<uint64_t>(std::llround(o.title_s * o.fps));
  if (!o.path.empty() && !container_for(o.path)) {
    throw std::invalid_argument("video: " + o.path.string() + ": the extension must be .mp4, .webm or .gif");
  }
  if (!o.frames_dir.empty()) {
    check_parent(o.frames_dir);
    if (fs::exists(o.frames_dir) && !(fs::is_directory(o.frames_dir) && fs::is_empty(o.frames_dir))) {
      throw std::invalid_argument("video: frames directory " + o.frames_dir.string() + " exists and is not empty");
    }
    s.frames_out = std::make_unique<io::AtomicDir>(o.frames_dir.string());
    s.frames_tmp = s.frames_out->temp_path();
    s.text_log.open(s.frames_tmp / "text.tsv");
    s.text_log << kTextLogHeader << '\n';
  }

  RenderOptions ro;
  ro.width_px = o.width_px;
  ro.height_px = o.height_px;
  ro.msaa_samples = o.msaa_samples;
  ro.shadows = o.shadows;
  ro.shadow_size = o.shadow_size;
  ro.reflections = o.reflections;
  ro.leave_overlay_room = o.overlay;
  ro.redraw_changed_only = o.redraw_changed_only;
  try {
    s.renderer = std::make_unique<OffscreenRenderer>(m, ro, o.camera);
    if (!o.path.empty()) {
      check_parent(o.path);
      s.video_file = std::make_unique<io::AtomicFile>(o.path.string());
      EncoderOptions eo;
      eo.width_px = o.width_px;
      eo.height_px = o.height_px;
      eo.fps = o.fps;
      eo.x264_preset = o.x264_preset;
      eo.crf = o.crf;
      eo.bottom_up = true;
      eo.container = *container_for(o.path);
      s.encoder = std::make_unique<FfmpegEncoder>(s.video_file->temp_path(), eo);
    }
  } catch (...) {
    s.discard_output();
    throw;
  }
  // The encoder's angle: joint "rotor" of the two-mass module (issue 14), or
  // "flange" in a one-joint model.
  int jnt = mj_name2id(m, mjOBJ_JOINT, "rotor");
  if (jnt < 0) jnt = mj_name2id(m, mjOBJ_JOINT, "flange");
  if (jnt >= 0) s.flange_qpos = m->jnt_qposadr[jnt];

  // Three buffers: one rendering, one being written, one spare (A-RENDERS-8).
  const std::size_t frame_bytes = static_cast<std::size_t>(o.width_px) * static_cast<std::size_t>(o.height_px) * 3;
  const std::size_t n_buffers = o.threaded ? 3 : 1;
  for (std::size_t i = 0; i < n_buffers; ++i) {
    s.buffers.emplace_back(frame_bytes);
    s.free_buffers.push_back(i);
  }
  if (o.threaded) s.writer = std::thread([&s] { s.writer_loop(); });
}

VideoRecorder::~VideoRecorder() {
  Impl& s = *impl_;
  s.stop_writer();
  if (!s.finished) s.discard_output();
}

double VideoRecorder::frame_time_s(uint64_t k) const {
  const Impl& s = *impl_;
  if (s.options.time_map) return s.options.time_map->sim_time(static_cast<double>(k) / s.options.fps);
  return static_cast<double>(k) / s.frame_rate_sim;
}
const TimeMap* VideoRecorder::time_map() const { return impl_->options.time_map ? &*impl_->options.time_map : nullptr; }
uint64_t VideoRecorder::frames_emitted() const {
  return impl_->next_frame + (impl_->title_done ? impl_->title_frames : 0);
}
uint64_t VideoRecorder::title_frames() const { return impl_->title_frames; }

bool VideoRecorder::wants_frame(double t_s) const { return t_s + 1e-9 >= frame_time_s(impl_->next_frame); }

void VideoRecorder::add_frame(const mjModel* m, const mjData* d, const FrameInfo& info) {
  uint64_t count = 0;
  while (wants_frame(info.row.t_s)) {
    ++count;
    ++impl_->next_frame;
  }
  impl_->next_frame -= count;
  hold(m, d, info, count);
}

void VideoRecorder::hold(const mjModel* m, const mjData* d, const FrameInfo& info, uint64_t count) {
  Impl& s = *impl_;
  if (s.finished) throw std::logic_error("VideoRecorder: add_frame after finish");
  if (count == 0) return;
  s.next_frame += count;
  const uint64_t first = s.next_frame - count;

  SceneState scene;
  scene.led = info.row.led;
  if (info.ghost_joint_rad) {
    scene.ghost_joint_rad = info.ghost_joint_rad;
  } else if (s.flange_qpos >= 0) {
    scene.ghost_joint_rad = flange_angle_rad(m, d) + (info.row.setpoint_deg - info.row.position_deg) * std::numbers::pi / 180.0;
  }
  if (s.options.overlay) {
    // The time scale is shown once, in the banner (issue 29).
    if (s.options.time_map) {
      scene.banner = s.options.time_map->segment_at(info.row.t_s).label();
    } else if (s.options.slowmo != 1.0) {
      scene.banner = fmt::format("slow motion {:g}x", s.options.slowmo);
    }
    scene.overlay = overlay_lines(info);
    scene.caption = info.caption;
  }

  // The title card goes before the run's first frame (issue 29): the
  // opening state dimmed, with the card's text.
  if (s.options.title && !s.title_done) {
    SceneState card = scene;
    card.title = s.options.title;
    card.pointer_labels = card.degree_scale = false; // the card's text alone over the dimmed scene
    s.queue(m, d, card, 0, s.title_frames);
    s.title_done = true;
  }
  s.queue(m, d, scene, s.title_frames + first, count);
}

void VideoRecorder::close(const mjModel* m, const mjData* d, const FrameInfo& info) {
  Impl& s = *impl_;
  if (!s.options.closing) return;
  if (s.finished) throw std::logic_error("VideoRecorder: close after finish");
  const auto count = static_cast<uint64_t>(std::llround(std::max(0.0, s.options.closing_s) * s.options.fps));
  SceneState card;
  card.led = info.row.led;
  card.ghost_joint_rad = info.ghost_joint_rad;
  card.title = s.options.closing;
  card.pointer_labels = card.degree_scale = false;
  s.queue(m, d, card, s.title_frames + s.next_frame, count);
  s.next_frame += count;
}

void VideoRecorder::finish() {
  Impl& s = *impl_;
  if (s.finished) throw std::logic_error("VideoRecorder: finish twice");
  s.stop_writer();
  try {
    if (s.error) std::rethrow_exception(s.error);
    if (s.next_frame == 0) throw std::runtime_error("video: no frame was recorded");
    if (s.encoder) {
      s.encoder->finish();
      s.encoder.reset();
      s.video_file->commit(); // ffmpeg wrote the temporary; rename it
    }
    if (s.text_log.is_open()) {
      s.text_log.close();
      if (!s.text_log) throw std::runtime_error("video: cannot write " + (s.frames_tmp / "text.tsv").string());
    }
    if (s.frames_out) s.frames_out->commit(); // replaces an empty folder, checked at start
  } catch (...) {
    s.discard_output();
    s.finished = true;
    throw;
  }
  s.finished = true;
}

} // namespace sreh
