// HTML report (issue 7): self-contained, shows the result, the expectations,
// the per-move times (manual 3.5.2 terms), the plots and the settling zoom
// (manual 3.5.2 Fig. 3), written atomically, renders in Chromium cleanly.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "renders/report.hpp"
#include "temp_dir.hpp"

namespace sreh {
namespace {

namespace fs = std::filesystem;

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A synthetic run: one 90 deg move starting at 0.1 s, 200 ms travel, the
// actual position lags and rings into the window, complete at 0.3345 s.
ReportInput sample_run(double cycle_s = 0.002, double duration_s = 0.6) {
  ReportInput in;
  in.scenario_name = "absolute move 90 deg <disk>";
  in.passed = true;
  in.checks = {{"state Done within 1.0 s", true}, {"position_deg in [89.9, 90.1]", true}, {"max_tracking_error_deg <= 0.5", true}};
  const auto n = static_cast<long>(std::llround(duration_s / cycle_s));
  for (long k = 0; k <= n; ++k) {
    TraceRow r;
    r.t_s = static_cast<double>(k) * cycle_s;
    const double u = std::clamp((r.t_s - 0.1) / 0.2, 0.0, 1.0);
    r.setpoint_deg = 90.0 * u * u * (3 - 2 * u);
    const double after = std::max(0.0, r.t_s - 0.3);
    r.position_deg = r.setpoint_deg - (u < 1 ? 0.3 * std::sin(M_PI * u) : 0.0) + (u >= 1 ? -0.2 * std::exp(-after / 0.01) * std::cos(after * 300) : 0.0);
    r.tracking_error_deg = r.setpoint_deg - r.position_deg;
    r.velocity_dps = 90.0 * 6 * u * (1 - u) / 0.2;
    r.torque_Nm = 0.3 * std::cos(M_PI * u) * (u > 0 && u < 1);
    r.torque_limit_Nm = 0.485;
    r.supply_V = 24.0;
    r.temperature_C = 25.0 + r.t_s;
    r.state = u <= 0 ? State::Ready : (r.t_s < 0.3345 ? State::Busy : State::Done);
    in.trace.push_back(r);
  }
  MoveRecord m;
  m.start_s = 0.1;
  m.travel_s = 0.2;
  m.settling_s = 0.0345;
  m.positioning_s = 0.2345;
  m.max_tracking_error_deg = 0.3;
  m.target_deg = 90.0;
  m.outcome = MoveOutcome::Done;
  m.tolerance_deg = 0.05; // each move's own set (issue 13)
  m.wait_ms = 20.0;
  in.moves = {m};
  in.tracking_limit_deg = 2.0;
  return in;
}

TEST(Report, ShowsResultChecksMoveTimesAndPlots) {
  const std::string html = report_html(sample_run());
  EXPECT_NE(html.find("PASSED"), std::string::npos);
  EXPECT_NE(html.find("absolute move 90 deg &lt;disk&gt;"), std::string::npos);
  EXPECT_NE(html.find("position_deg in [89.9, 90.1]"), std::string::npos);
  // manual 3.5.2: travel (1), settling (2), positioning (4) times in ms.
  EXPECT_NE(html.find("<td>200.0</td><td>34.5</td><td>234.5</td>"), std::string::npos);
  // 6 plots over time + 1 settling zoom.
  EXPECT_EQ(count(html, "<svg"), 7u);
  EXPECT_NE(html.find("tracking limit (index 87)"), std::string::npos);
  EXPECT_NE(html.find("motor limit"), std::string::npos);
  EXPECT_NE(html.find("tolerance window (5)"), std::string::npos);
  EXPECT_NE(html.find("waiting time (3) 20 ms"), std::string::npos);
  EXPECT_NE(html.find("(f) complete"), std::string::npos);
  EXPECT_EQ(html.find("<video"), std::string::npos);
  // Self-contained: nothing fetched from elsewhere, no scripts.
  EXPECT_EQ(html.find("http://"), html.find("http://www.w3.org/2000/svg"));
  EXPECT_EQ(html.find("https://"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
}

TEST(Report, FailedRunAndIncompleteMoveAreMarked) {
  ReportInput in = sample_run();
  in.passed = false;
  in.checks.push_back({"warning_code == 0", false});
  in.moves[0].outcome = MoveOutcome::Error;
  in.moves[0].settling_s.reset();
  in.moves[0].positioning_s.reset();
  const std::string html = report_html(in);
  EXPECT_NE(html.find("FAILED"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"bad\">FAIL</td>"), std::string::npos);
  EXPECT_NE(html.find("not completed"), std::string::npos);
  EXPECT_NE(html.find("<td>200.0</td><td>&mdash;</td><td>&mdash;</td>"), std::string::npos);
}

TEST(Report, EmbedsTheVideoWhenRendered) {
  ReportInput in = sample_run();
  in.video_file = "run.mp4";
  EXPECT_NE(report_html(in).find("<video src=\"run.mp4\" controls"), std::string::npos);
}

TEST(Report, LongTracesAreDecimatedSoTheHtmlStaysSmall) {
  // 5 minutes at 1 ms: 300k rows.
  const std::string html = report_html(sample_run(0.001, 300.0));
  EXPECT_LT(html.size(), 800u * 1024u);
}

TEST(Report, WrittenAtomicallyIntoTheDirectory) {
  test::TempDir tmp;
  const fs::path dir = tmp / "report";
  fs::create_directories(dir);
  std::ofstream(dir / "index.html") << "old";
  const fs::path index = write_report(dir, sample_run());
  EXPECT_EQ(index, dir / "index.html");
  const std::string html = slurp(index);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("</html>"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "index.html.tmp"));
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1u);
}

TEST(Report, UnwritableDirectoryThrowsAndLeavesNothing) {
  test::TempDir tmp;
  std::ofstream(tmp / "file") << "x";
  EXPECT_THROW(write_report(tmp / "file" / "report", sample_run()), std::runtime_error);
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(tmp.path())) ++entries;
  EXPECT_EQ(entries, 1u);
}

// The report opens in a real browser without console errors.
TEST(Report, RendersInHeadlessChromiumWithoutConsoleErrors) {
  if (!test::on_path("chromium")) GTEST_SKIP() << "chromium not installed";
  test::TempDir tmp;
  const fs::path index = write_report(tmp / "report", sample_run());
  const fs::path profile = tmp / "profile";
  const fs::path err = tmp / "stderr.txt";
  // `timeout` only guards against a hung browser; nothing is timed.
  const std::string cmd = "timeout 300 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
                          "--disable-background-networking --disable-component-update --disable-sync "
                          "--enable-logging=stderr --v=0 --user-data-dir='" + profile.string() + "' --dump-dom 'file://" +
                          index.string() + "' 2>'" + err.string() + "'";
  const std::string dom = test::run_capture(cmd);
  const std::string log = slurp(err);
  EXPECT_NE(dom.find("<svg"), std::string::npos) << log;
  EXPECT_NE(dom.find("PASSED"), std::string::npos);
  EXPECT_EQ(log.find("CONSOLE"), std::string::npos) << log;
  EXPECT_EQ(log.find("Uncaught"), std::string::npos) << log;
}

} // namespace
} // namespace sreh
