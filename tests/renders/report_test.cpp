// HTML report (issue 7, 16): a movable folder, summary on top, the
// expectations, the per-move times (manual 3.5.2 terms), zoomable plots with
// readable SVG axes and the settling zoom (manual 3.5.2 Fig. 3), written
// atomically, renders in Chromium cleanly and plays its video there.
#include <deque>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <set>
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
// Every src= / href= of the page's elements.
std::vector<std::string> links(const std::string& html) {
  std::vector<std::string> out;
  const std::regex attr(R"re(<[a-z]+ [^>]*(src|href)="([^"]*)")re");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), attr); it != std::sregex_iterator(); ++it) out.push_back((*it)[2]);
  return out;
}

ReportCheck check(const std::string& description, bool passed, const std::string& step = "3", const std::string& actual = "") {
  return {description, passed, step, 7, 0.25, actual};
}

// ReportInput only points at rows and records: the samples' live here.
template <typename T>
std::span<const T> keep(std::vector<T> v) {
  static std::deque<std::vector<T>> store;
  store.push_back(std::move(v));
  return store.back();
}

ReportInput sample_run(double cycle_s = 0.002, double duration_s = 0.6) {
  ReportInput in;
  std::vector<TraceRow> trace;
  in.scenario_name = "absolute move 90 deg <disk>";
  in.passed = true;
  in.checks = {check("state Done within 1.0 s", true), check("position_deg in [89.9, 90.1]", true),
               check("max_tracking_error_deg <= 0.5", true)};
  in.command_line = "sreh-twin run 'my scenario.yaml' --report out";
  in.version = "9.9.9";
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
    trace.push_back(r);
  }
  in.trace = keep(std::move(trace));
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
  in.moves = keep(std::vector<MoveRecord>{m});
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
  // The run's command line and version.
  EXPECT_NE(html.find("sreh-twin run &#39;my scenario.yaml&#39; --report out"), std::string::npos);
  EXPECT_NE(html.find("sreh-twin 9.9.9"), std::string::npos);
  // Self-contained: nothing fetched from elsewhere; dygraphs is inlined.
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_TRUE(links(html).empty());
  EXPECT_NE(html.find("Dygraph"), std::string::npos);
  // One zoomable twin for each of the 6 plots over time.
  EXPECT_EQ(count(html, "srehPlot(\"dy-"), 6u);
}

// Issue 16: every <svg> plot carries >= 6 distinct numeric tick labels as
// plain <text> numbers (ASCII minus, units only in the axis titles).
TEST(Report, EverySvgPlotHasSixDistinctNumericTickLabels) {
  const std::string html = report_html(sample_run());
  const std::regex number(R"(<text[^>]*>(-?[0-9]+(\.[0-9]+)?)</text>)");
  std::size_t svgs = 0;
  for (std::size_t a = html.find("<svg"); a != std::string::npos; a = html.find("<svg", a + 1)) {
    const std::string svg = html.substr(a, html.find("</svg>", a) - a);
    std::set<std::string> labels;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), number); it != std::sregex_iterator(); ++it) labels.insert((*it)[1]);
    EXPECT_GE(labels.size(), 6u) << svg.substr(0, 300);
    EXPECT_EQ(labels.count("-0"), 0u);
    ++svgs;
  }
  EXPECT_EQ(svgs, 7u);
  EXPECT_EQ(html.find("\xE2\x88\x92"), std::string::npos); // no Unicode minus
}

// The tracking error is scaled to the data; the index-87 limit far above it
// is named at the plot's edge instead of flattening the curve.
TEST(Report, TrackingPlotScalesToTheDataAndNamesAnOffScaleLimit) {
  const std::string html = report_html(sample_run());
  const std::size_t a = html.find("id=\"dy-p-tracking\"");
  ASSERT_NE(a, std::string::npos);
  const std::size_t svg = html.find("<svg", a);
  const std::string plot = html.substr(svg, html.find("</svg>", svg) - svg);
  EXPECT_NE(plot.find("tracking limit (index 87) (2, off scale)"), std::string::npos);
  EXPECT_EQ(plot.find(">2.0<"), std::string::npos);
}

TEST(Report, FailedRunAndIncompleteMoveAreMarked) {
  ReportInput in = sample_run();
  in.passed = false;
  in.checks.push_back(check("expect warning_code 0", false, "9", "warning_code 0x02"));
  std::vector<MoveRecord> moves(in.moves.begin(), in.moves.end());
  moves[0].outcome = MoveOutcome::Error;
  moves[0].settling_s.reset();
  moves[0].positioning_s.reset();
  in.moves = keep(std::move(moves));
  const std::string html = report_html(in);
  EXPECT_NE(html.find("FAILED"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"badc\">FAIL</td>"), std::string::npos);
  // The summary on top names each failed check with its step and value.
  const std::size_t failed = html.find("<ul class=\"failed\"");
  ASSERT_NE(failed, std::string::npos);
  EXPECT_LT(failed, html.find("<h2>"));
  EXPECT_NE(html.find("step 9 (line 7): expect warning_code 0 &mdash; got warning_code 0x02", failed), std::string::npos);
  EXPECT_NE(html.find("not completed"), std::string::npos);
  EXPECT_NE(html.find("<td>200.0</td><td>&mdash;</td><td>&mdash;</td>"), std::string::npos);
}

// Issue 29: a step inside a repeat checks once per pass under one number;
// the table tells the passes apart by the scenario line and the pass.
TEST(Report, RepeatedStepsAreToldApart) {
  ReportInput in = sample_run();
  in.checks = {{"position_deg in [179.98, 180.02]", true, "4.6", 30, 0.5, "180.001"},
               {"position_deg in [179.98, 180.02]", false, "4.6", 30, 1.5, "179.9"}};
  in.passed = false;
  const std::string html = report_html(in);
  EXPECT_NE(html.find("<td>4.6 <span class=\"note\">(line 30)</span></td>"), std::string::npos);
  EXPECT_NE(html.find("<td>4.6 <span class=\"note\">(line 30, pass 2)</span></td>"), std::string::npos);
  EXPECT_NE(html.find("<li>step 4.6 (line 30, pass 2): position_deg"), std::string::npos);
}

// Issue 29: setpoint and actual told apart by more than colour.
TEST(Report, SetpointIsDashedUnderTheActual) {
  const std::string html = report_html(sample_run());
  EXPECT_NE(html.find("setpoint (A), dashed"), std::string::npos);
  const std::size_t svg = html.find("id=\"svg-p-position\"");
  ASSERT_NE(svg, std::string::npos);
  EXPECT_NE(html.find("stroke-dasharray", svg), std::string::npos);
}

TEST(Report, CommissioningHintsStandAtTheTop_Issue28) {
  ReportInput in = sample_run();
  in.hints = {"hint: parameter set 1 is configured for 0 g cm^2, the attached load is 7200 g cm^2 (manual 3.5.6, 7.2)"};
  const std::string html = report_html(in);
  const std::size_t hint = html.find("<ul class=\"hints\" id=\"hints\">");
  ASSERT_NE(hint, std::string::npos);
  EXPECT_NE(html.find("configured for 0 g cm^2, the attached load is 7200 g cm^2", hint), std::string::npos);
  EXPECT_LT(hint, html.find("<h2>Expectations</h2>")); // above everything but the result line
  EXPECT_EQ(report_html(sample_run()).find("id=\"hints\""), std::string::npos);
}

TEST(Report, CopiesTheVideoInSoTheFolderCanBeMoved) {
  test::TempDir tmp;
  std::ofstream(tmp / "run.mp4") << "not really a video";
  ReportInput in = sample_run();
  in.video_source = tmp / "run.mp4";
  write_report(tmp / "report", in);
  fs::rename(tmp / "report", tmp / "moved");
  fs::remove(tmp / "run.mp4");
  const std::string html = slurp(tmp / "moved" / "index.html");
  EXPECT_NE(html.find("<video id=\"video\" src=\"video.mp4\" controls"), std::string::npos);
  EXPECT_EQ(slurp(tmp / "moved" / "video.mp4"), "not really a video");
  EXPECT_EQ(links(html), std::vector<std::string>{"video.mp4"}); // nothing outside the folder
}

TEST(Report, LongTracesAreDecimatedSoTheHtmlStaysSmall) {
  // 5 minutes at 1 ms: 300k rows.
  const std::string html = report_html(sample_run(0.001, 300.0));
  EXPECT_LT(html.size(), 800u * 1024u);
  EXPECT_NE(html.find("(f) complete"), std::string::npos); // the settling zoom read back from the spooled rows
}

// Issue 12: a trace longer than kReportFullRateRows is read back in pieces
// and only min/max rows are kept, yet every single-row extreme of every
// plotted series still reaches the plots.
TEST(Report, LongTraceKeepsEverySeriesExtremes) {
  ReportInput in = sample_run(0.001, 300.0);
  ASSERT_GT(in.trace.size(), kReportFullRateRows);
  std::vector<TraceRow> rows(in.trace.begin(), in.trace.end());
  rows[123457].velocity_dps = 4321.5;
  rows[200001].temperature_C = 98.25;
  rows[55555].torque_Nm = -0.4375;
  rows[277777].supply_V = 17.125;
  rows[99999].external_torque_Nm = 0.0625;
  rows[250000].tracking_error_deg = -1.75;
  in.trace = keep(std::move(rows));
  const std::string html = report_html(in);
  for (const char* extreme : {",4321.5", ",98.25", ",-0.4375", ",17.125", ",0.0625", ",-1.75"}) {
    EXPECT_NE(html.find(extreme), std::string::npos) << extreme;
  }
  EXPECT_NE(html.find("external torque"), std::string::npos); // seen in a row the decimation need not keep
}

TEST(ReportRecorder, ReadsRowsBackAndFindsTimes) {
  ReportRecorder run;
  for (int k = 0; k < 10000; ++k) {
    TraceRow r;
    r.t_s = 0.002 * k;
    r.position_deg = k;
    run.add_row(r);
  }
  ASSERT_EQ(run.rows(), 10000u);
  std::vector<TraceRow> got(3);
  run.read_rows(4097, got);
  EXPECT_EQ(got[0].position_deg, 4097);
  EXPECT_EQ(got[2].position_deg, 4099);
  EXPECT_EQ(run.lower_bound(1.0), 500u);  // t = 1.0 s is row 500
  EXPECT_EQ(run.upper_bound(1.0), 501u);
  EXPECT_EQ(run.lower_bound(-1), 0u);
  EXPECT_EQ(run.upper_bound(1e9), 10000u);
}

TEST(ReportRecorder, CountsChecksAndMovesAndKeepsOnlyTheZoomedMoves) {
  ReportRecorder run;
  for (int i = 0; i < 30; ++i) {
    MoveRecord m;
    m.outcome = i % 3 ? MoveOutcome::Done : MoveOutcome::Error;
    run.add_move(m);
  }
  run.add_check(check("a <b>", true));
  run.add_check(check("c", false, "9", "x"));
  EXPECT_EQ(run.moves(), 30u);
  EXPECT_EQ(run.moves_completed(), 20u);
  EXPECT_EQ(run.zoomed_moves().size(), kMaxSettlingPlots);
  EXPECT_EQ(run.checks(), 2u);
  EXPECT_EQ(run.checks_held(), 1u);
  std::ostringstream rows, failed;
  run.copy_check_rows(rows);
  run.copy_failed_items(failed);
  EXPECT_NE(rows.str().find("a &lt;b&gt;"), std::string::npos);
  EXPECT_EQ(failed.str(), "<li>step 9 (line 7): c &mdash; got x at t = 0.250 s</li>\n");
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

// The report opens in a real browser without console errors, draws its
// zoomable plots and plays its (H.264) video: Debian's Chromium decodes it.
TEST(Report, RendersInHeadlessChromiumAndPlaysTheVideo) {
  if (!test::on_path("chromium")) GTEST_SKIP() << "chromium not installed";
  if (!test::on_path("ffmpeg")) GTEST_SKIP() << "ffmpeg not installed";
  test::TempDir tmp;
  const fs::path clip = tmp / "clip.mp4";
  test::run_capture("ffmpeg -v error -f lavfi -i testsrc=size=160x120:rate=10 -t 2 -c:v libx264 -pix_fmt yuv420p -y '" +
                    clip.string() + "'");
  ASSERT_TRUE(fs::exists(clip));
  ReportInput in = sample_run();
  in.video_source = clip;
  const fs::path index = write_report(tmp / "report", in);
  // A probe appended to a copy of the page reports into the title.
  std::string html = slurp(index);
  html.insert(html.rfind("</body>"),
              "<script>var v=document.getElementById('video');"
              "v.addEventListener('error',function(){document.title='VIDEO-ERROR '+(v.error&&v.error.code)});"
              "v.play().then(function(){setTimeout(function(){document.title='PLAYING t='+v.currentTime+' w='+v.videoWidth"
              "+' live='+document.querySelectorAll('.fig.live canvas').length},1000)})"
              ".catch(function(e){document.title='REJECTED '+e});</script>");
  std::ofstream(tmp / "report" / "probe.html") << html;
  const fs::path profile = tmp / "profile";
  const fs::path err = tmp / "stderr.txt";
  // `timeout` only guards against a hung browser; nothing is timed.
  const std::string cmd = "timeout 300 chromium --headless=new --no-sandbox --disable-gpu --disable-quic --no-first-run "
                          "--disable-background-networking --disable-component-update --disable-sync "
                          "--autoplay-policy=no-user-gesture-required --virtual-time-budget=5000 "
                          "--enable-logging=stderr --v=0 --user-data-dir='" + profile.string() + "' --dump-dom 'file://" +
                          (tmp / "report" / "probe.html").string() + "' 2>'" + err.string() + "'";
  const std::string dom = test::run_capture(cmd);
  const std::string log = slurp(err);
  EXPECT_NE(dom.find("<svg"), std::string::npos) << log;
  EXPECT_NE(dom.find("PASSED"), std::string::npos);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(dom, m, std::regex("<title>PLAYING t=([0-9.]+) w=([0-9]+) live=([0-9]+)</title>"))) << dom.substr(0, 400);
  EXPECT_GT(std::stod(m[1]), 0.0);  // time advanced: the video plays
  EXPECT_EQ(m[2], "160");           // and was decoded
  EXPECT_GE(std::stoi(m[3]), 6);    // dygraphs drew (canvases in live figures)
  EXPECT_EQ(log.find("Uncaught"), std::string::npos) << log;
}

} // namespace
} // namespace sreh
