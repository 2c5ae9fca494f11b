// Sizing and sweep reports (issue 8): self-contained HTML with the plots and
// the numbers, written atomically (no .tmp left behind).
#include <gtest/gtest.h>

#include <filesystem>

#include <fmt/format.h>

#include "io/html_page.hpp"
#include "sizing/limit_names.hpp"
#include "sizing/output.hpp"
#include "sizing/report.hpp"
#include "sizing/uncertainty.hpp"
#include "tests/sizing/report_checks.hpp"

namespace sreh::sizing {
namespace {

namespace fs = std::filesystem;

TEST(Report, SizeReportHasPlotsNumbersAndWrites) {
  if (!reports_available()) GTEST_SKIP() << "built without renders";
  SizingRequest rq;
  rq.angle_deg = 30;
  rq.world.load = InertiaLoad{1000};
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
  EXPECT_NE(html.find("continuous torque"), std::string::npos);
  const std::size_t svgs = test::count_svgs_with_ticks(html);
  EXPECT_EQ(svgs, 6u);
  // Issue 17: temperature from ambient under the cycle's mean loss, with the warning and the trip.
  EXPECT_NE(html.find("Module temperature"), std::string::npos);
  EXPECT_NE(html.find("75 degC trip (error 114.3)"), std::string::npos);
  EXPECT_NE(html.find("70 degC warning (115.1)"), std::string::npos);
  EXPECT_NE(html.find("time to 75 degC trip (114.3)"), std::string::npos);

  const fs::path dir = fs::path(testing::TempDir()) / "sreh_sizing_report_test";
  fs::remove_all(dir);
  const fs::path index = write_size_report(dir, rq, r);
  EXPECT_TRUE(fs::exists(index));
  EXPECT_FALSE(fs::exists(dir / "index.html.tmp"));
  EXPECT_EQ(test::file_text(index), html);
  fs::remove_all(dir);
}

// Issue 29: the page opens with the verdict block, and its figures are the
// ones `size --json` (and the text) prints, rounded as the text rounds them.
TEST(Report, SizeReportOpensWithTheVerdictOfTheJson) {
  if (!reports_available()) GTEST_SKIP() << "built without renders";
  SizingRequest rq;
  rq.angle_deg = 90;
  rq.world.load = InertiaLoad{2000};
  rq.cycles = 1;
  rq.keep_trace = true;
  const SizingResult r = size(rq);
  const nlohmann::json j = to_json(rq, r);
  const std::string html = size_report_html(rq, r);
  const std::size_t verdict = html.find("<section class=\"verdict\" id=\"verdict\">");
  ASSERT_NE(verdict, std::string::npos);
  EXPECT_LT(verdict, html.find("<h2>")); // before everything else
  const nlohmann::json& u = j["utilisation"];
  EXPECT_NE(html.find(j["feasible"].get<bool>() ? ">FEASIBLE<" : ">NOT FEASIBLE<"), std::string::npos);
  EXPECT_NE(html.find(fmt::format("<b id=\"binding-limit\">{}</b>", io::html_escape(limit_in_words(j["binding_limit"].get<std::string>())))), std::string::npos);
  EXPECT_NE(html.find(fmt::format("<td>{:.0f} %</td>", u["peak_torque_pct"].get<double>())), std::string::npos);
  EXPECT_NE(html.find(fmt::format("<td>{:.0f} %</td>", u["rms_torque_pct"].get<double>())), std::string::npos);
  EXPECT_NE(html.find(fmt::format("<td>margin {:.1f} K</td>", u["thermal_margin_K"].get<double>())), std::string::npos);
  EXPECT_NE(html.find(fmt::format("<td>{:.1f} deg/s</td>", j["recommended"]["speed_dps"].get<double>())), std::string::npos);
  EXPECT_NE(html.find(fmt::format("J_load / J_intern = {:.2f}", j["request"]["load_gcm2"].get<double>() / 1150.0)), std::string::npos);
  EXPECT_NE(html.find(fmt::format("peak {:.2f} A, RMS {:.2f} A", j["supply"]["peak_current_A"].get<double>(),
                                  j["supply"]["rms_current_A"].get<double>())),
            std::string::npos);
  for (const char* bar : {"bar-peak", "bar-rms", "bar-thermal", "bar-speed"}) {
    EXPECT_NE(html.find(fmt::format("<tr id=\"{}\">", bar)), std::string::npos) << bar;
  }
  // The temperature plot reaches past the trip: both lines drawn on scale, none "off scale".
  const std::size_t t = html.find("id=\"svg-temperature\"");
  ASSERT_NE(t, std::string::npos);
  const std::string svg = html.substr(t, html.find("</svg>", t) - t);
  std::size_t limits = 0;
  for (std::size_t a = svg.find("class=\"limit\""); a != std::string::npos; a = svg.find("class=\"limit\"", a + 1)) ++limits;
  EXPECT_GE(limits, 2u);
  EXPECT_EQ(svg.find("off scale"), std::string::npos);
  EXPECT_NE(svg.find(">80<"), std::string::npos); // a tick at or above the trip
}

// size --report --uncertainty (issue 26): the bands on the page, read
// against the nominal: a table with the ranges, shaded bands in the torque
// and temperature plots; none of it without --uncertainty.
TEST(Report, SizeReportShowsTheUncertaintyBands) {
  if (!reports_available()) GTEST_SKIP() << "built without renders";
  SizingRequest rq;
  rq.angle_deg = 90;
  rq.world.load = InertiaLoad{5000};
  rq.setting = MotionSetting{2000, 100, 100};
  rq.cycles = 1;
  rq.keep_trace = true;
  const SizingResult r = size(rq);
  const UncertaintyResult u = size_uncertainty(rq, default_model_card(), r.evaluation, 4, 5, 2);
  ASSERT_GT(u.banded, 0);
  const std::string html = size_report_html(rq, r, &u);
  EXPECT_NE(html.find("Over the model's uncertainty"), std::string::npos);
  const Band& b = u.peak_torque_Nm;
  EXPECT_NE(html.find(fmt::format("<td>{:.3f}</td><td>{:.3f}</td><td>{:.3f}</td><td>{:.3f}</td><td>{:.3f}</td>", b.lo, b.p5,
                                  b.median, b.p95, b.hi)),
            std::string::npos);
  // Issue 35: the badge is the verdict over every sample, never a plain FEASIBLE above it.
  EXPECT_NE(html.find(u.feasible_worst_case ? ">FEASIBLE IN EVERY SAMPLE<" : ">NOT FEASIBLE IN EVERY SAMPLE<"), std::string::npos);
  EXPECT_EQ(html.find(">FEASIBLE<"), std::string::npos);
  EXPECT_EQ(html.find(">NOT FEASIBLE<"), std::string::npos);
  for (const std::string& name : u.sampled) EXPECT_NE(html.find(name), std::string::npos) << name;
  EXPECT_NE(html.find("peak torque over the sampled models"), std::string::npos);
  EXPECT_NE(html.find("steady temperature over the sampled models"), std::string::npos);
  const std::string plain = size_report_html(rq, r);
  EXPECT_EQ(plain.find("Over the model's uncertainty"), std::string::npos);
  EXPECT_EQ(plain.find("over the sampled models"), std::string::npos);
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
  // Issue 29: no page per point, so a verdict row per point, from its CSV row's figures.
  const std::size_t table = html.find("<table class=\"verdicts\" id=\"verdicts\">");
  ASSERT_NE(table, std::string::npos);
  const std::string rows = html.substr(table, html.find("</table>", table) - table);
  std::size_t n = 0;
  for (std::size_t a = rows.find("<td class=\"mini\">"); a != std::string::npos; a = rows.find("<td class=\"mini\">", a + 1)) ++n;
  EXPECT_EQ(n, 4u * r.points.size()); // four bars per point
  const Evaluation& e = r.points.back().result.evaluation;
  EXPECT_NE(rows.find(fmt::format("{:.0f} %", e.utilisation.peak_torque_pct)), std::string::npos);
  EXPECT_NE(rows.find(fmt::format("{:.1f} K", e.utilisation.thermal_margin_K)), std::string::npos);
}

} // namespace
} // namespace sreh::sizing
