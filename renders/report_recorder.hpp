// A run collected for its report while it runs (issue 12): the memory it
// takes does not grow with run length. Trace rows go to a private temporary
// file (io::Spool) as fixed-size records and are read back in pieces; each
// check and move is formatted into its table row (and a failed check into
// the summary's list) in temporaries of their own. Held in memory: counts
// and the first kMaxSettlingPlots move records (the settling zooms).
#pragma once
#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "io/spool.hpp"
#include "twin/trace.hpp"

namespace sreh {

struct ReportCheck {
  std::string description;
  bool passed = false;
  std::string step;   // "4", "expect"
  int line = 0;       // scenario line; 0: none
  double t_s = 0;     // when it was decided
  std::string actual; // the value observed
};

// Settling zooms drawn at most (the table lists every move).
inline constexpr std::size_t kMaxSettlingPlots = 24;

class ReportRecorder {
 public:
  // Throws std::runtime_error if a temporary file cannot be created.
  ReportRecorder();

  // In the run's order: rows in time order, checks as decided, moves as final.
  void add_row(const TraceRow& row);
  void add_check(const ReportCheck& check);
  void add_move(const MoveRecord& move);

  std::size_t rows() const { return rows_; }
  // Rows [begin, begin + out.size()) read back.
  void read_rows(std::size_t begin, std::span<TraceRow> out);
  TraceRow row(std::size_t i);
  // The first row with t_s >= t (lower) or > t (upper); rows() if none.
  std::size_t lower_bound(double t_s);
  std::size_t upper_bound(double t_s);

  std::size_t checks() const { return checks_; }
  std::size_t checks_held() const { return checks_held_; }
  std::size_t moves() const { return moves_; }
  std::size_t moves_completed() const { return moves_completed_; }
  // The first kMaxSettlingPlots moves, for their settling zooms.
  const std::vector<MoveRecord>& zoomed_moves() const { return zoomed_moves_; }

  // The formatted pieces: <tr> rows of the checks and moves tables, <li>
  // items of the failed checks.
  void copy_check_rows(std::ostream& out) { check_rows_.copy_to(out); }
  void copy_failed_items(std::ostream& out) { failed_items_.copy_to(out); }
  void copy_move_rows(std::ostream& out) { move_rows_.copy_to(out); }

 private:
  template <bool Upper>
  std::size_t bound(double t_s);

  io::Spool trace_, check_rows_, failed_items_, move_rows_;
  std::size_t rows_ = 0, checks_ = 0, checks_held_ = 0, moves_ = 0, moves_completed_ = 0;
  std::vector<MoveRecord> zoomed_moves_;
  std::map<std::string, int> step_passes_; // checks seen per step number and line (a repeat's passes)
};

} // namespace sreh
