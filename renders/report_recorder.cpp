#include "renders/report_recorder.hpp"

#include <ostream>
#include <type_traits>

#include <fmt/format.h>

#include "io/html_page.hpp"

namespace sreh {

// Rows are spooled as their bytes: a plain record, no pointers inside.
static_assert(std::is_trivially_copyable_v<TraceRow>);

namespace {

using io::html_escape;

std::string ms(double s) { return s < 0 ? std::string("&mdash;") : fmt::format("{:.1f}", s * 1e3); }

} // namespace

ReportRecorder::ReportRecorder() = default;

void ReportRecorder::add_row(const TraceRow& row) {
  trace_.stream().write(reinterpret_cast<const char*>(&row), sizeof row);
  ++rows_;
}

void ReportRecorder::add_check(const ReportCheck& ch) {
  ++checks_;
  checks_held_ += ch.passed ? 1 : 0;
  // A step inside a repeat checks once per pass under the same number
  // (issue 29: "4.2" twice): its scenario line and the pass tell them apart.
  const int pass = ++step_passes_[fmt::format("{}@{}", ch.step, ch.line)];
  const std::string where = ch.line > 0 ? fmt::format("line {}", ch.line) : std::string();
  const std::string which = pass > 1 ? fmt::format("{}{}pass {}", where, where.empty() ? "" : ", ", pass) : where;
  check_rows_.stream() << fmt::format(
      "<tr><td>{}{}</td><td class=\"l\">{}</td><td class=\"l\">{}</td><td class=\"{}\">{}</td></tr>\n", html_escape(ch.step),
      which.empty() ? std::string() : " <span class=\"note\">(" + which + ")</span>", html_escape(ch.description),
      html_escape(ch.actual), ch.passed ? "okc" : "badc", ch.passed ? "pass" : "FAIL");
  if (ch.passed) return;
  failed_items_.stream() << fmt::format("<li>step {}{}: {} &mdash; got {} at t = {:.3f} s</li>\n", html_escape(ch.step),
                                        which.empty() ? std::string() : " (" + which + ")", html_escape(ch.description),
                                        html_escape(ch.actual.empty() ? "-" : ch.actual), ch.t_s);
}

void ReportRecorder::add_move(const MoveRecord& m) {
  ++moves_;
  moves_completed_ += m.completed() ? 1 : 0;
  if (zoomed_moves_.size() < kMaxSettlingPlots) zoomed_moves_.push_back(m);
  move_rows_.stream() << fmt::format(
      "<tr><td>{}</td><td>{:.3f}</td><td>{:.3f}</td><td>{}</td><td>{}</td><td>{}</td><td>{:.4f}</td><td class=\"{}\">{}</td></tr>\n",
      moves_, m.start_s, m.target_deg, ms(m.travel_s), ms(m.settling_s.value_or(-1)), ms(m.positioning_s.value_or(-1)),
      m.max_tracking_error_deg, m.completed() ? "okc" : "badc", m.completed() ? "yes" : "no");
}

void ReportRecorder::read_rows(std::size_t begin, std::span<TraceRow> out) {
  if (out.empty()) return;
  trace_.read_at(static_cast<unsigned long long>(begin) * sizeof(TraceRow), out.data(), out.size_bytes());
}

TraceRow ReportRecorder::row(std::size_t i) {
  TraceRow r;
  read_rows(i, {&r, 1});
  return r;
}

template <bool Upper>
std::size_t ReportRecorder::bound(double t_s) {
  std::size_t lo = 0, hi = rows_;
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    const double t = row(mid).t_s;
    if (Upper ? t <= t_s : t < t_s) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

std::size_t ReportRecorder::lower_bound(double t_s) { return bound<false>(t_s); }
std::size_t ReportRecorder::upper_bound(double t_s) { return bound<true>(t_s); }

} // namespace sreh
