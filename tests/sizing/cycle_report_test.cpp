// The cycle's sizing report (issue 17): the speed-torque plane with the
// voltage-dependent envelope, the operating points and the RMS point; the
// time per segment; temperature from ambient; written atomically.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "sizing/cycle.hpp"
#include "io/html_page.hpp"
#include "sizing/limit_names.hpp"
#include "sizing/report.hpp"
#include "tests/sizing/report_checks.hpp"

namespace sreh::sizing {
namespace {

namespace fs = std::filesystem;

TEST(CycleReport, HasTheSpeedTorquePlaneSegmentTimesAndTemperature) {
  if (!reports_available()) GTEST_SKIP() << "built without renders";
  CycleRequest rq = parse_cycle_file(std::string(SREH_SOURCE_DIR) + "/tests/sizing/data/load_change_cycle.yaml");
  rq.keep_trace = true;
  const CycleResult r = size_cycle(rq);
  ASSERT_FALSE(r.evaluation.trace.empty());
  const std::string html = cycle_report_html(rq, r);
  EXPECT_NE(html.find("Speed-torque plane"), std::string::npos);
  EXPECT_NE(html.find("envelope 24.0 V"), std::string::npos);  // the supply's envelope (manual 3.5.3)
  EXPECT_NE(html.find("envelope 16 V"), std::string::npos);    // and the others for comparison
  EXPECT_NE(html.find("RMS point"), std::string::npos);
  EXPECT_NE(html.find("move 2 (segment 4)"), std::string::npos); // operating points per move
  EXPECT_NE(html.find("Time per segment"), std::string::npos);
  EXPECT_NE(html.find("Module temperature"), std::string::npos);
  // Issue 29: the same verdict block as the single move's, before the numbers.
  const std::size_t verdict = html.find("id=\"verdict\"");
  ASSERT_NE(verdict, std::string::npos);
  EXPECT_LT(verdict, html.find("<h2>Numbers</h2>"));
  EXPECT_NE(html.find(fmt::format("<b id=\"binding-limit\">{}</b>", io::html_escape(limit_in_words(r.evaluation.binding_limit)))), std::string::npos);
  EXPECT_NE(html.find(fmt::format("<td>margin {:.1f} K</td>", r.evaluation.utilisation.thermal_margin_K)), std::string::npos);
  EXPECT_NE(html.find("75 degC trip (error 114.3)"), std::string::npos);
  EXPECT_NE(html.find("- isdu_write: {index: 66, subindex: 4, value: 12000}"), std::string::npos);
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  const std::size_t svgs = test::count_svgs_with_ticks(html);
  EXPECT_EQ(svgs, 5u); // segment times, speed-torque, temperature, torque, position

  const fs::path dir = fs::path(testing::TempDir()) / "sreh_cycle_report_test";
  fs::remove_all(dir);
  const fs::path index = write_cycle_report(dir, rq, r);
  EXPECT_EQ(test::file_text(index), html);
  fs::remove_all(dir);
}

} // namespace
} // namespace sreh::sizing
