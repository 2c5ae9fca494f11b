// Off-screen rendering of the module (issue 7): images are real, respond to
// the flange angle, the LED band colour (manual 3.1 LED states) and the ghost.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "render_fixture.hpp"
#include "renders/offscreen.hpp"

namespace sreh {
namespace {

class OffscreenTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    md_ = new test::ModelData();
    RenderOptions o;
    o.width_px = 320;
    o.height_px = 240;
    renderer_ = new OffscreenRenderer(md_->m, o);
  }
  static void TearDownTestSuite() {
    delete renderer_;
    delete md_;
  }
  void SetUp() override {
    md_->set_flange(0.0);
    renderer_->set_camera(CameraSpec{});
  }
  static RgbImage render(const SceneState& s = {}) { return renderer_->render(md_->m, md_->d, s); }

  static test::ModelData* md_;
  static OffscreenRenderer* renderer_;
};
test::ModelData* OffscreenTest::md_ = nullptr;
OffscreenRenderer* OffscreenTest::renderer_ = nullptr;

double luminance_variance(const RgbImage& img) {
  double sum = 0, sum2 = 0;
  const std::size_t n = img.rgb.size() / 3;
  for (std::size_t i = 0; i < n; ++i) {
    const double l = (img.rgb[3 * i] + img.rgb[3 * i + 1] + img.rgb[3 * i + 2]) / 3.0;
    sum += l;
    sum2 += l * l;
  }
  const double mean = sum / static_cast<double>(n);
  return sum2 / static_cast<double>(n) - mean * mean;
}

std::size_t differing_pixels(const RgbImage& a, const RgbImage& b, int threshold = 24) {
  std::size_t n = 0;
  for (std::size_t i = 0; i + 2 < a.rgb.size(); i += 3) {
    const int d = std::abs(a.rgb[i] - b.rgb[i]) + std::abs(a.rgb[i + 1] - b.rgb[i + 1]) + std::abs(a.rgb[i + 2] - b.rgb[i + 2]);
    if (d > threshold) ++n;
  }
  return n;
}

TEST_F(OffscreenTest, FrameIsNotBlank) {
  const RgbImage img = render();
  ASSERT_EQ(img.rgb.size(), 320u * 240u * 3u);
  EXPECT_GT(luminance_variance(img), 100.0);
}

TEST_F(OffscreenTest, SameStateRendersPixelIdentical) {
  EXPECT_EQ(render().rgb, render().rgb);
}

TEST_F(OffscreenTest, FramesDifferWhenTheFlangeTurns) {
  const RgbImage a = render();
  md_->set_flange(1.2);
  const RgbImage b = render();
  EXPECT_GT(differing_pixels(a, b), 200u);
}

TEST_F(OffscreenTest, CameraFramingDoesNotFollowTheLoadRotation) {
  // The auto framing uses a bounding cylinder about the flange axis: turning
  // the flange by a full revolution gives the identical picture.
  const RgbImage a = render();
  md_->set_flange(2.0 * M_PI);
  renderer_->set_camera(CameraSpec{});
  const RgbImage b = render();
  EXPECT_LT(differing_pixels(a, b), 20u);
}

TEST_F(OffscreenTest, GhostShowsTheSetpointAngleWithoutTouchingTheData) {
  SceneState s;
  s.ghost_joint_rad = 0.0;
  const RgbImage a = render(s);
  s.ghost_joint_rad = 1.5;
  const RgbImage b = render(s);
  EXPECT_GT(differing_pixels(a, b), 50u);
  const int body = mj_name2id(md_->m, mjOBJ_BODY, "setpoint_ghost");
  const double* q = md_->d->mocap_quat + 4 * md_->m->body_mocapid[body];
  EXPECT_EQ(q[0], 1.0) << "the renderer must not write the twin's mjData";
  EXPECT_EQ(q[3], 0.0);
}

TEST_F(OffscreenTest, GhostSitsOnTopOfTheLoad) {
  // In test_module.xml the ghost body sits at the flange face, under the
  // load disk: only the lift onto the load makes it visible from above.
  renderer_->set_camera(CameraSpec::top());
  SceneState s;
  s.ghost_joint_rad = 0.0;
  const RgbImage a = render(s);
  s.ghost_joint_rad = 1.0;
  const RgbImage b = render(s);
  EXPECT_GT(differing_pixels(a, b), 100u);
}

TEST_F(OffscreenTest, TopViewDiffersFromDefaultView) {
  const RgbImage a = render();
  renderer_->set_camera(CameraSpec::top());
  const RgbImage b = render();
  EXPECT_GT(differing_pixels(a, b), 1000u);
}

TEST_F(OffscreenTest, OverlayTextIsDrawnTopLeft) {
  const RgbImage a = render();
  SceneState s;
  s.overlay = {{"t", "1.234 s"}, {"state", "Busy"}};
  const RgbImage b = render(s);
  std::size_t changed_top_left = 0;
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 160; ++x)
      if (a.at(x, y) != b.at(x, y)) ++changed_top_left;
  EXPECT_GT(changed_top_left, 50u);
}

// Manual 3.1 / index 83: the LED band shows the state colour. The band's
// pixels are found as those that change between two distinct colours; their
// mean colour must then point the way the set colour points.
void expect_led_band_takes_the_set_colour(OffscreenRenderer& r, const mjModel* m, mjData* d) {
  auto render = [&](LedColor c) {
    SceneState s;
    s.led = c;
    return r.render(m, d, s);
  };
  const RgbImage ir = render(LedColor::Red), ib = render(LedColor::Blue);
  std::vector<std::pair<int, int>> band;
  for (int y = 0; y < ir.height; ++y)
    for (int x = 0; x < ir.width; ++x) {
      const auto a = ir.at(x, y), b = ib.at(x, y);
      if (a[0] > b[0] + 80 && b[2] > a[2] + 80) band.emplace_back(x, y);
    }
  ASSERT_GT(band.size(), 30u) << "LED band not visible";

  auto mean_colour = [&](LedColor c) {
    const RgbImage img = render(c);
    std::array<double, 3> mean{};
    for (auto [x, y] : band)
      for (std::size_t k = 0; k < 3; ++k) mean[k] += img.at(x, y)[k];
    for (double& v : mean) v /= static_cast<double>(band.size());
    return mean;
  };
  for (LedColor c : {LedColor::Green, LedColor::Yellow, LedColor::Blue, LedColor::Red, LedColor::Orange,
                     LedColor::White, LedColor::Violet}) {
    const auto mean = mean_colour(c);
    const auto want = led_look(c).rgba;
    double dot = 0, nm = 0, nw = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      dot += mean[k] * want[k];
      nm += mean[k] * mean[k];
      nw += double(want[k]) * want[k];
    }
    EXPECT_GT(dot / std::sqrt(nm * nw), 0.97) << led_name(c) << " rendered " << mean[0] << "," << mean[1] << "," << mean[2];
  }
  const auto off = mean_colour(LedColor::Off);
  const auto white = mean_colour(LedColor::White);
  EXPECT_LT(off[0] + off[1] + off[2], 0.4 * (white[0] + white[1] + white[2])) << "off must look dark";
  EXPECT_NEAR(off[0], off[2], 20.0) << "off must look grey, not coloured";
}

TEST_F(OffscreenTest, LedBandPixelsTakeTheSetColour) { expect_led_band_takes_the_set_colour(*renderer_, md_->m, md_->d); }

// The module model the twin uses (models/sreh50.xml): frames well, LED band
// visible from the default camera, ghost and flange move the picture.
TEST(OffscreenModuleModel, RendersTheRealModuleWithItsLedBandAndGhost) {
  const std::string path = std::string(SREH_SOURCE_DIR) + "/models/sreh50.xml";
  char error[1000] = "";
  mjModel* m = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
  if (!m) GTEST_SKIP() << "models/sreh50.xml not loadable: " << error;
  mjData* d = mj_makeData(m);
  mj_forward(m, d);
  {
    RenderOptions o;
    o.width_px = 320;
    o.height_px = 180;
    OffscreenRenderer r(m, o);
    const RgbImage a = r.render(m, d, {});
    EXPECT_GT(luminance_variance(a), 100.0);
    expect_led_band_takes_the_set_colour(r, m, d);
    SceneState ghost;
    ghost.ghost_joint_rad = 2.0;
    EXPECT_GT(differing_pixels(a, r.render(m, d, ghost)), 20u);
    d->qpos[m->jnt_qposadr[mj_name2id(m, mjOBJ_JOINT, "flange")]] = 1.0;
    mj_forward(m, d);
    EXPECT_GT(differing_pixels(a, r.render(m, d, {})), 20u);
    r.set_camera([] { CameraSpec c; c.model_camera = "front"; return c; }());
    EXPECT_GT(luminance_variance(r.render(m, d, {})), 100.0);
  }
  mj_deleteData(d);
  mj_deleteModel(m);
}

// Issue 29: the degree scale is drawn on the housing and stays there when
// the flange turns; the pointer labels turn with the flange.
TEST(OffscreenModuleModel, ScaleStaysOnHousingLabelsTurnWithFlange) {
  const std::string path = std::string(SREH_SOURCE_DIR) + "/models/sreh50.xml";
  char error[1000] = "";
  mjModel* m = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
  if (!m) GTEST_SKIP() << "models/sreh50.xml not loadable: " << error;
  mjData* d = mj_makeData(m);
  const int flange_q = m->jnt_qposadr[mj_name2id(m, mjOBJ_JOINT, "flange")];
  {
    RenderOptions o;
    o.width_px = 640;
    o.height_px = 360;
    OffscreenRenderer r(m, o, CameraSpec::top());
    // The pixels a decoration changes, with the flange at `rad`.
    auto marks = [&](double rad, bool scale) {
      d->qpos[flange_q] = rad;
      mj_forward(m, d);
      SceneState with, without;
      with.degree_scale = scale;
      with.pointer_labels = !scale;
      without.degree_scale = without.pointer_labels = false;
      const RgbImage a = r.render(m, d, with), b = r.render(m, d, without);
      std::vector<bool> changed(static_cast<std::size_t>(a.width * a.height));
      for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) changed[static_cast<std::size_t>(y * a.width + x)] = a.at(x, y) != b.at(x, y);
      return changed;
    };
    auto overlap = [](const std::vector<bool>& p, const std::vector<bool>& q) {
      std::size_t both = 0, n = 0;
      for (std::size_t i = 0; i < p.size(); ++i) {
        n += p[i] ? 1 : 0;
        both += p[i] && q[i] ? 1 : 0;
      }
      return std::pair{n, n == 0 ? 0.0 : static_cast<double>(both) / static_cast<double>(n)};
    };
    const auto [scale_px, scale_kept] = overlap(marks(0.0, true), marks(1.0, true));
    EXPECT_GT(scale_px, 300u) << "36 ticks and four numbers";
    EXPECT_GT(scale_kept, 0.8) << "the scale must stay with the housing";
    const auto [label_px, label_kept] = overlap(marks(0.0, false), marks(1.0, false));
    EXPECT_GT(label_px, 40u) << "the pointer's label";
    EXPECT_LT(label_kept, 0.3) << "the label must turn with the flange";
  }
  mj_deleteData(d);
  mj_deleteModel(m);
}

} // namespace
} // namespace sreh
