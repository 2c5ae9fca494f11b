// Self-contained HTML report of one scenario run (issue 7): result, the
// expectations, the per-move table (manual 3.5.2 terms), plots over time and
// a settling zoom per move (manual 3.5.2 Fig. 3), the video when rendered.
// One file, inline SVG and CSS, no scripts, no external fetches.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "twin/trace.hpp"

namespace sreh {

struct ReportCheck {
  std::string description;
  bool passed = false;
};

struct ReportInput {
  std::string scenario_name;
  bool passed = false;
  std::vector<ReportCheck> checks;
  std::vector<TraceRow> trace;
  std::vector<MoveRecord> moves;   // the device's records: each with its own set's tolerance and waiting time
  double tracking_limit_deg = 0; // index 87 limit drawn on the tracking-error plot; 0: none
  std::string video_file;        // relative to the report directory; empty: no video
};

// Settling zooms drawn at most (the table lists every move).
inline constexpr std::size_t kMaxSettlingPlots = 24;

// The HTML text of the report.
std::string report_html(const ReportInput& in);

// Writes dir/index.html atomically (index.html.tmp, then rename); creates
// `dir` if missing. Returns the file's path. Throws std::runtime_error.
std::filesystem::path write_report(const std::filesystem::path& dir, const ReportInput& in);

// Writes `text` to `path` through `path`.tmp and a rename.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

} // namespace sreh
