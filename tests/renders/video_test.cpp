// Video recording (issue 7): H.264 MP4 through ffmpeg and PNG frames, frames
// due by integer index, output written atomically (F.tmp renamed).
#include <gtest/gtest.h>

#include <mujoco/mujoco.h>
#include <png.h>

#include <fstream>

#include <fmt/format.h>

#include "render_fixture.hpp"
#include "renders/video.hpp"
#include "temp_dir.hpp"

namespace sreh {
namespace {

namespace fs = std::filesystem;

class VideoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!test::on_path("ffmpeg")) GTEST_SKIP() << "ffmpeg not installed";
  }
  VideoOptions small(const fs::path& path) const {
    VideoOptions o;
    o.path = path;
    o.width_px = 160;
    o.height_px = 120;
    o.msaa_samples = 0;
    return o;
  }
  // Drives the recorder like the twin does: on 2 ms IO-Link cycle
  // boundaries, time from the integer cycle count.
  static void drive(VideoRecorder& rec, test::ModelData& md, int cycles) {
    for (int c = 0; c <= cycles; ++c) {
      const double t_s = c * 0.002;
      md.set_flange(t_s * 3.0);
      if (!rec.wants_frame(t_s)) continue;
      FrameInfo f;
      f.row.t_s = t_s;
      f.row.state = State::Busy;
      f.row.led = LedColor::Green;
      rec.add_frame(md.m, md.d, f);
    }
  }
  test::ModelData md_;
  test::TempDir dir_;
};

// Frame k of a --frames folder as 8-bit gray pixels; empty if unreadable.
std::vector<uint8_t> gray_frame(const fs::path& dir, uint64_t k) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  const std::string file = (dir / fmt::format("frame_{:06d}.png", k)).string();
  std::vector<uint8_t> raw;
  if (!png_image_begin_read_from_file(&png, file.c_str())) return raw;
  png.format = PNG_FORMAT_GRAY;
  raw.resize(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, raw.data(), 0, nullptr)) raw.clear();
  return raw;
}

int probe_frames(const fs::path& mp4) {
  const std::string out = test::run_capture("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                                            "stream=nb_read_frames,codec_name,pix_fmt,width -of csv=p=0 '" +
                                            mp4.string() + "'");
  // "h264,160,yuv420p,N"
  EXPECT_NE(out.find("h264,160,yuv420p,"), std::string::npos) << out;
  return std::atoi(out.substr(out.rfind(',') + 1).c_str());
}

TEST_F(VideoTest, WritesH264Mp4AtomicallyWithOneFramePerDueIndex) {
  const fs::path mp4 = dir_ / "run.mp4";
  VideoRecorder rec(md_.m, small(mp4));
  drive(rec, md_, 500); // 1.0 s at 30 fps: frames 0..30
  EXPECT_EQ(rec.frames_emitted(), 31u);
  EXPECT_FALSE(fs::exists(mp4)) << "nothing under the final name before finish";
  rec.finish();
  EXPECT_TRUE(fs::exists(mp4));
  EXPECT_FALSE(fs::exists(dir_ / "run.mp4.tmp"));
  EXPECT_FALSE(fs::exists(dir_ / "run.mp4.tmp.log"));
  EXPECT_EQ(probe_frames(mp4), 31);
}

TEST_F(VideoTest, FrameTimesComeFromTheIndexNotAccumulatedTime) {
  VideoOptions o = small(dir_ / "a.mp4");
  o.slowmo = 4.0;
  VideoRecorder rec(md_.m, o);
  EXPECT_DOUBLE_EQ(rec.frame_time_s(3), 3.0 / 30.0 / 4.0);
  EXPECT_TRUE(rec.wants_frame(0.0));
  // 3000 frames later the due time is still exact: k / fps / slowmo.
  EXPECT_DOUBLE_EQ(rec.frame_time_s(3000), 25.0);
}

TEST_F(VideoTest, SlowMotionEmitsSeveralFramesPerCycleWhenDenser) {
  VideoOptions o = small(dir_ / "slow.mp4");
  o.slowmo = 100.0; // 3000 frames per simulated second, 6 per 2 ms cycle
  VideoRecorder rec(md_.m, o);
  drive(rec, md_, 5); // t = 0 .. 10 ms
  EXPECT_EQ(rec.frames_emitted(), 31u); // frames 0..30 have t <= 10 ms
  rec.finish();
  EXPECT_EQ(probe_frames(o.path), 31);
}

TEST_F(VideoTest, PngFramesGoToTheirDirectory) {
  VideoOptions o = small({});
  o.frames_dir = dir_ / "frames";
  VideoRecorder rec(md_.m, o);
  drive(rec, md_, 50); // 0.1 s: frames 0..3
  rec.finish();
  EXPECT_FALSE(fs::exists(dir_ / "frames.tmp"));
  ASSERT_TRUE(fs::exists(o.frames_dir / "frame_000003.png"));
  EXPECT_FALSE(fs::exists(o.frames_dir / "frame_000004.png"));
  std::ifstream png(o.frames_dir / "frame_000000.png", std::ios::binary);
  char sig[8] = {};
  png.read(sig, 8);
  EXPECT_EQ(std::string(sig + 1, 3), "PNG");
}

TEST_F(VideoTest, DestroyedWithoutFinishLeavesNothing) {
  VideoOptions o = small(dir_ / "gone.mp4");
  o.frames_dir = dir_ / "frames";
  {
    VideoRecorder rec(md_.m, o);
    drive(rec, md_, 50);
  }
  EXPECT_TRUE(fs::is_empty(dir_.path()));
}

TEST_F(VideoTest, FfmpegFailureThrowsAndLeavesNothing) {
  VideoOptions o = small(dir_ / "bad.mp4");
  o.x264_preset = "no-such-preset"; // ffmpeg refuses to open the encoder
  EXPECT_THROW(
      {
        VideoRecorder rec(md_.m, o);
        drive(rec, md_, 500);
        rec.finish();
      },
      std::runtime_error);
  EXPECT_TRUE(fs::is_empty(dir_.path()));
}

TEST_F(VideoTest, RejectsBadOptions) {
  VideoOptions o = small(dir_ / "x.mp4");
  o.width_px = 161;
  EXPECT_THROW(VideoRecorder(md_.m, o), std::invalid_argument);
  o = small({});
  EXPECT_THROW(VideoRecorder(md_.m, o), std::invalid_argument);
  o = small(dir_ / "no_such_dir" / "x.mp4");
  EXPECT_THROW(VideoRecorder(md_.m, o), std::invalid_argument);
  o = small(dir_ / "x.mp4");
  o.slowmo = 0;
  EXPECT_THROW(VideoRecorder(md_.m, o), std::invalid_argument);
  fs::create_directory(dir_ / "full");
  std::ofstream(dir_ / "full" / "keep.txt") << "x";
  o = small({});
  o.frames_dir = dir_ / "full";
  EXPECT_THROW(VideoRecorder(md_.m, o), std::invalid_argument);
  EXPECT_TRUE(fs::exists(dir_ / "full" / "keep.txt"));
}

TEST(OverlayLines, ShowStepTargetSetAndCodesButNotTheTimeScale) {
  FrameInfo f;
  f.row.t_s = 1.5;
  f.row.state = State::ErrorOn;
  f.row.error_code = 0x08;
  f.step = "4 wait_until";
  f.row.pd_out = encode(ProcessDataOut{.target_raw = 16384, .parameter_set = 2}); // 90 deg (2^16 counts/rev)
  const auto lines = overlay_lines(f);
  auto value = [&](const std::string& label) {
    for (const auto& [l, v] : lines)
      if (l == label) return v;
    return std::string("<missing>");
  };
  EXPECT_EQ(value("t"), "1.5000 s");
  EXPECT_EQ(value("state"), "ErrorOn");
  EXPECT_EQ(value(""), "step 4 wait_until"); // spans both columns
  EXPECT_EQ(value("target"), "90.00 deg");
  EXPECT_EQ(value("set"), "2");
  EXPECT_EQ(value("err/warn"), "0x08/none");
  EXPECT_EQ(value("LED"), "off");
  // Issue 29: the time scale is the banner's alone, never a row as well.
  for (const auto& [l, v] : lines) EXPECT_EQ(v.find("slow motion"), std::string::npos) << l;
  f.step.clear();
  EXPECT_EQ(overlay_lines(f).size(), lines.size() - 1);
}

// Issue 29: the title card comes first for title_s, then the run's frames
// at their usual indices shifted by the card's length.
TEST_F(VideoTest, TitleCardPrecedesTheRunsFirstFrame) {
  VideoOptions o = small({});
  o.frames_dir = dir_ / "titled";
  o.title = TitleCard{"a scenario", {{"load", "no load"}, {"set 1", "360 deg/s, accel 100 %, jerk 100 %"}}};
  o.fps = 10;
  o.title_s = 0.5;
  VideoRecorder rec(md_.m, o);
  EXPECT_EQ(rec.title_frames(), 5u); // 0.5 s at 10 fps
  drive(rec, md_, 50);
  const uint64_t run_frames = rec.frames_emitted() - rec.title_frames();
  rec.finish();
  std::size_t pngs = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "titled")) pngs += e.path().extension() == ".png" ? 1 : 0;
  EXPECT_EQ(pngs, rec.frames_emitted());
  EXPECT_GT(run_frames, 0u);
  // The card (frames 0..4) is one image, the dimmed scene with text: many
  // pixels differ from the run's first frame.
  auto pixels = [&](uint64_t k) { return gray_frame(dir_ / "titled", k); };
  const std::vector<uint8_t> card = pixels(0), run = pixels(5);
  ASSERT_EQ(card.size(), 160u * 120u);
  ASSERT_EQ(run.size(), card.size());
  EXPECT_EQ(pixels(4), card);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < card.size(); ++i) differ += std::abs(card[i] - run[i]) > 12 ? 1 : 0;
  EXPECT_GT(differ, card.size() / 4);
}

// Issue 31: redrawing only what can change gives the frames a full redraw
// gives, while the flange turns and the overlay's values change. Stale
// pixels (a part outside the redrawn box) would differ here.
TEST_F(VideoTest, RedrawingOnlyTheChangingPartGivesTheFullFrames) {
  // The module model itself: the box must fit it tightly (a box shifted by
  // half the eye distance once left part of the LED band stale at 1080p).
  char error[1000] = "";
  mjModel* m = mj_loadXML((std::string(SREH_SOURCE_DIR) + "/models/sreh50.xml").c_str(), nullptr, error, sizeof error);
  ASSERT_NE(m, nullptr) << error;
  mjData* d = mj_makeData(m);
  const int rotor_q = m->jnt_qposadr[mj_name2id(m, mjOBJ_JOINT, "rotor")];
  auto record = [&](bool partial, const char* name) {
    VideoOptions o = small({});
    o.width_px = 640;
    o.height_px = 360;
    o.msaa_samples = 4;
    o.fps = 20;
    o.slowmo = 10; // a banner, and several frames per cycle
    o.redraw_changed_only = partial;
    o.frames_dir = dir_ / name;
    VideoRecorder rec(m, o);
    for (int c = 0; c <= 60; ++c) {
      const double t_s = c * 0.002;
      d->qpos[rotor_q] = t_s * 20.0;
      mj_forward(m, d);
      if (!rec.wants_frame(t_s)) continue;
      FrameInfo f;
      f.row.t_s = t_s;
      f.row.state = c < 30 ? State::Busy : State::Ready;
      f.row.position_deg = t_s * 20.0 * 57.3;
      f.row.setpoint_deg = f.row.position_deg + 3;
      f.step = c < 30 ? "3 wait_until" : "12 isdu_write_and_wait_long_name";
      f.row.led = c < 30 ? LedColor::Yellow : LedColor::Blue;
      rec.add_frame(m, d, f);
    }
    rec.finish();
    return rec.frames_emitted();
  };
  const uint64_t n = record(false, "full");
  ASSERT_EQ(record(true, "partial"), n);
  ASSERT_GT(n, 10u);
  auto gray = [&](const char* name, uint64_t k) { return gray_frame(dir_ / name, k); };
  for (uint64_t k = 0; k < n; ++k) {
    const std::vector<uint8_t> a = gray("full", k), b = gray("partial", k);
    ASSERT_EQ(a.size(), 640u * 360u) << k;
    ASSERT_EQ(b.size(), a.size()) << k;
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.size(); ++i) differ += std::abs(a[i] - b[i]) > 24 ? 1 : 0;
    EXPECT_LT(differ, a.size() / 1000) << "frame " << k; // < 0.1 %: depth ties of coplanar faces only
  }
  mj_deleteData(d);
  mj_deleteModel(m);
}

// Issue 39: the closing card follows the run's last frame; every card text
// is wrapped, never cut; the caption shows; frames/text.tsv records what each
// frame shows and where.
TEST_F(VideoTest, ClosingCardCaptionsAndTheTextLog) {
  VideoOptions o = small({});
  o.width_px = 320;
  o.height_px = 240;
  o.frames_dir = dir_ / "log";
  o.fps = 10;
  o.title_s = 0.5;
  o.closing_s = 1.0;
  const std::string name = "a scenario with a name much too long for one line of a small frame, said in full";
  o.title = TitleCard{name, {{"load", "gripper with jaws and a part on an adapter (gripper_with_part.yaml)"}}};
  o.closing = TitleCard{"PASS: all 3 checks held", {{"final state", "Ready at 90.00 deg, LED green"}}};
  VideoRecorder rec(md_.m, o);
  for (int c = 0; c <= 100; ++c) {
    const double t_s = c * 0.002;
    md_.set_flange(t_s * 3.0);
    if (!rec.wants_frame(t_s)) continue;
    FrameInfo f;
    f.row.t_s = t_s;
    f.row.state = State::Busy;
    f.caption = "pick at 0 deg, swivel to the place position at 180 deg";
    rec.add_frame(md_.m, md_.d, f);
  }
  FrameInfo last;
  last.row.t_s = 0.2;
  rec.close(md_.m, md_.d, last);
  const uint64_t n = rec.frames_emitted();
  EXPECT_EQ(n, 5u + 3u + 10u); // title 0.5 s, run frames 0..2 (0.2 s at 10 fps), closing 1 s
  rec.finish();
  std::ifstream log(dir_ / "log" / "text.tsv");
  std::string line;
  std::getline(log, line);
  EXPECT_EQ(line, kTextLogHeader);
  std::string title, closing, caption;
  while (std::getline(log, line)) {
    // first_frame, last_frame, kind, x, y, width, height, then the text.
    std::vector<std::string> col;
    std::size_t at = 0;
    for (int i = 0; i < 7; ++i) {
      const std::size_t tab = line.find('\t', at);
      ASSERT_NE(tab, std::string::npos) << line;
      col.push_back(line.substr(at, tab - at));
      at = tab + 1;
    }
    const std::string text = line.substr(at);
    const uint64_t first = std::stoull(col[0]), last_frame = std::stoull(col[1]);
    EXPECT_GT(std::stoi(col[5]), 0) << line;
    EXPECT_LT(std::stoi(col[3]) + std::stoi(col[5]), 320 + 1) << "inside the frame: " << line;
    EXPECT_EQ(text.find("..."), std::string::npos) << "cut: " << line;
    if (col[2] == "card" && first == 0) title += (title.empty() ? "" : " ") + text;
    if (col[2] == "card" && last_frame == n - 1) closing += (closing.empty() ? "" : " ") + text;
    if (col[2] == "caption" && first == 5) caption += (caption.empty() ? "" : " ") + text;
  }
  EXPECT_NE(title.find(name), std::string::npos) << title;
  EXPECT_NE(title.find("gripper with jaws and a part on an adapter (gripper_with_part.yaml)"), std::string::npos) << title;
  EXPECT_EQ(closing.rfind("PASS: all 3 checks held", 0), 0u) << closing;
  EXPECT_NE(closing.find("Ready at 90.00 deg, LED green"), std::string::npos) << closing;
  EXPECT_EQ(caption, "pick at 0 deg, swivel to the place position at 180 deg");
  // The closing card is one image over its frames, unlike the run's last frame.
  const std::vector<uint8_t> card = gray_frame(dir_ / "log", n - 1), run = gray_frame(dir_ / "log", 7);
  ASSERT_EQ(card.size(), 320u * 240u);
  EXPECT_EQ(gray_frame(dir_ / "log", n - 10), card);
  EXPECT_NE(run, card);
}

} // namespace
} // namespace sreh
