// Self-contained report folder of one scenario run (issue 7, 16): a summary
// on top (pass/fail, each failed check with its step and value), the run's
// command line and version, the video (copied into the folder), the per-move
// table (manual 3.5.2 terms), zoomable plots over time (dygraphs inlined,
// static SVG for print) and a settling zoom per move (manual 3.5.2 Fig. 3).
// No links out of the folder, no external fetches: it can be moved. Made
// from a ReportRecorder, so a long run's report takes no more memory than a
// short one's (issue 12).
#pragma once
#include <filesystem>
#include <iosfwd>
#include <span>
#include <string>
#include <vector>

#include "renders/report_recorder.hpp"
#include "twin/trace.hpp"

namespace sreh {

// What the report says besides the recorded rows, checks and moves.
struct ReportSummary {
  std::string scenario_name;
  bool passed = false;
  double tracking_limit_deg = 0; // index 87 limit drawn on the tracking-error plot; 0: none
  std::string command_line;      // how the run was started
  std::string version;           // sreh-twin version
  double sim_time_s = 0;
  double max_tracking_error_deg = 0;
  std::vector<std::string> hints; // commissioning hints (issue 28), shown at the top
  // A rendered video (.mp4, .webm, .gif) copied into the folder as
  // video.<ext>; empty: no video.
  std::filesystem::path video_source;
};

// A run already in memory (tests, small runs): recorded into a
// ReportRecorder on the way in, so that there is one report path.
struct ReportInput : ReportSummary {
  std::vector<ReportCheck> checks;
  // The run's own rows and records, not copies: they must outlive the call.
  std::span<const TraceRow> trace;
  std::span<const MoveRecord> moves; // the device's records: each with its own set's tolerance and waiting time
};

// Up to this many rows every row is plotted; a longer trace is read back in
// pieces and only the rows a min/max plot needs are kept (renders/report.cpp).
inline constexpr std::size_t kReportFullRateRows = std::size_t{1} << 16;

// The HTML page, written to `out` as it is made; `video_name` is the
// video's file name inside the folder (empty: none).
void write_report_html(std::ostream& out, const ReportSummary& summary, ReportRecorder& run,
                       const std::string& video_name = "");
std::string report_html(const ReportInput& in, const std::string& video_name = "");

// Copies the video in (video.<ext>), then writes dir/index.html, each
// through io::write_file_atomic; creates `dir` if missing (one level: its
// parent must exist). Returns the index's path. Throws std::runtime_error.
std::filesystem::path write_report(const std::filesystem::path& dir, const ReportSummary& summary, ReportRecorder& run);
std::filesystem::path write_report(const std::filesystem::path& dir, const ReportInput& in);

} // namespace sreh
