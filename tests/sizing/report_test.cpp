// Sizing and sweep reports (issue 8): self-contained HTML with the plots and
// the numbers, written atomically (no .tmp left behind).
#include <gtest/gtest.h>

#include <filesystem>

#include "sizing/report.hpp"
#include "tests/sizing/report_checks.hpp"

namespace sreh::sizing {
namespace {

namespace fs = std::filesystem;

TEST(Report, SizeReportHasPlotsNumbersAndWrites) {
  if (!reports_available()) GTEST_SKIP() << "built without renders";
  SizingRequest rq;
  rq.angle_deg = 30;
  rq.load = InertiaLoad{1000};
  rq.setting = MotionSetting{1000, 100, 100};
  rq.cycles = 1;
  rq.keep_trace = true;
  const SizingResult r = size(rq);
  ASSERT_FALSE(r.evaluation.trace.empty());
  const std::string html = size_report_html(rq, r);
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("Motor torque"), std::string::npos);
  EXPECT_NE(html.find("Velocity"), std::string::npos);
  EXPECT_NE(html.find("- isdu_write: {index: 65, subindex: 1, value: 10000}"), std::string::npos);
  // Issue 16: zoomable plots with the packaged dygraphs inlined (no fetch),
  // a speed-torque plot, and every SVG with >= 6 distinct numeric ticks.
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_NE(html.find("srehPlot("), std::string::npos);
  EXPECT_NE(html.find("Speed-torque"), std::string::npos);
  EXPECT_NE(html.find("capability (motoring)"), std::string::npos);
  EXPECT_NE(html.find("RMS point"), std::string::npos); // issue 17
  EXPECT_NE(html.find("continuous torque (A-SIZE-14)"), std::string::npos);
  const std::size_t svgs = test::count_svgs_with_ticks(html);
  EXPECT_EQ(svgs, 6u);
  // Issue 17: temperature from ambient under the cycle's mean loss, with the warning and the trip.
  EXPECT_NE(html.find("Module temperature"), std::string::npos);
  EXPECT_NE(html.find("75 degC error (114.3)"), std::string::npos);
  EXPECT_NE(html.find("time to 75 degC trip (114.3)"), std::string::npos);

  const fs::path dir = fs::path(testing::TempDir()) / "sreh_sizing_report_test";
  fs::remove_all(dir);
  const fs::path index = write_size_report(dir, rq, r);
  EXPECT_TRUE(fs::exists(index));
  EXPECT_FALSE(fs::exists(dir / "index.html.tmp"));
  EXPECT_EQ(test::file_text(index), html);
  fs::remove_all(dir);
}

TEST(Report, SweepReportHasBothPlots) {
  if (!reports_available()) GTEST_SKIP() << "built without renders";
  SweepRequest rq;
  rq.loads_gcm2 = {0, 3000};
  rq.angles_deg = {30};
  rq.speeds_dps = {1500};
  rq.base.cycles = 1;
  const SweepResult r = run_sweep(rq);
  const std::vector<double> targets = default_targets_s(r);
  ASSERT_FALSE(targets.empty());
  const std::string html = sweep_report_html(rq, r, targets);
  EXPECT_NE(html.find("Positioning time vs load"), std::string::npos);
  EXPECT_NE(html.find("Heaviest load"), std::string::npos);
}

} // namespace
} // namespace sreh::sizing
