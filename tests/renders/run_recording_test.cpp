// A run kept for its video (issue 16), spooled to a temporary file so that
// memory does not grow with run length (issue 12): the stretches of motion
// the time map needs, and frames rendered from the samples read back.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "render_fixture.hpp"
#include "renders/run_recording.hpp"
#include "temp_dir.hpp"

namespace sreh {
namespace {

namespace fs = std::filesystem;

// 2 s at 2 ms; the flange turns during samples 100..199 and 500..599.
void record(RunRecording& rec, test::ModelData& md) {
  for (int k = 0; k < 1000; ++k) {
    FrameInfo f;
    f.row.t_s = 0.002 * k;
    const bool turning = (k >= 100 && k < 200) || (k >= 500 && k < 600);
    f.row.moving = turning;
    f.row.state = turning ? State::Busy : State::Ready;
    f.row.position_deg = k < 100 ? 0.0 : k < 200 ? 0.9 * (k - 100) : k < 500 ? 90.0 : k < 600 ? 90.0 - 0.9 * (k - 500) : 0.0;
    f.step = k < 300 ? "3 move" : "4 move";
    md.set_flange(f.row.position_deg * M_PI / 180.0);
    rec.add(md.d, f);
  }
}

std::string slurp_recording(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(RunRecording, KeepsTheStretchesOfMotionAndTheRunsLength) {
  test::ModelData md;
  RunRecording rec(md.m);
  record(rec, md);
  EXPECT_EQ(rec.samples(), 1000u);
  EXPECT_DOUBLE_EQ(rec.duration_s(), 0.002 * 999);
  // A sample closes the cycle before it: motion from the sample before the first moving one.
  const auto& motion = rec.motion();
  ASSERT_EQ(motion.size(), 2u);
  EXPECT_DOUBLE_EQ(motion[0].first, 0.002 * 99);
  EXPECT_DOUBLE_EQ(motion[0].second, 0.002 * 199);
  EXPECT_DOUBLE_EQ(motion[1].first, 0.002 * 499);
  EXPECT_DOUBLE_EQ(motion[1].second, 0.002 * 599);
}

TEST(RunRecording, RendersFramesFromTheSamplesReadBack) {
  if (!test::on_path("ffmpeg")) GTEST_SKIP() << "ffmpeg not installed";
  test::TempDir dir;
  test::ModelData md;
  RunRecording rec(md.m);
  record(rec, md);
  VideoOptions o;
  o.width_px = 160;
  o.height_px = 120;
  o.msaa_samples = 0;
  o.overlay = false; // frames then differ only by the pose
  o.frames_dir = dir / "frames";
  fs::create_directories(o.frames_dir);
  const VideoSummary summary = rec.render(o, /*fixed_slowmo=*/true);
  // 1.998 s at 30 fps: frames 0..59, then the end state held 0.5 s (A-RENDERS-12).
  EXPECT_EQ(summary.frames, 60u + 15u);
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(o.frames_dir)) files += e.path().extension() == ".png" ? 1 : 0;
  EXPECT_EQ(files, summary.frames);
  EXPECT_TRUE(fs::exists(o.frames_dir / "text.tsv")); // the frames' words (issue 39); none drawn here but the header
  // The flange stands at 0 deg at the start and at the end, at 90 deg between the moves.
  auto frame = [&](int k) { return slurp_recording(o.frames_dir / fmt::format("frame_{:06d}.png", k)); };
  const std::string start = frame(0);
  ASSERT_FALSE(start.empty());
  EXPECT_TRUE(start == frame(5));      // t = 0.167 s: not moved yet
  EXPECT_FALSE(start == frame(9));     // 0.3 s: half way (45 deg)
  EXPECT_FALSE(frame(9) == frame(12)); // 0.4 s: 90 deg
  EXPECT_TRUE(frame(12) == frame(20)); // 0.667 s: still 90 deg
  EXPECT_TRUE(start == frame(59));     // 1.967 s: back at 0
  EXPECT_TRUE(start == frame(74));     // the held end state
}

} // namespace
} // namespace sreh
