// Settling as a distribution where it is chaotic (issue 35, A-SIZE-24):
// the time into a tight tolerance window can move by many milliseconds for
// a target a few position counts away (stick-slip at the window's edge),
// while its median over such targets converges. `size` runs its answer's
// set again with targets up to N counts either side and reports the
// median and p95 when the spread exceeds 1 ms, and whether every move held
// the window for good (if not: the smallest window that did).
#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "sizing/sizing.hpp"
#include "sizing/uncertainty.hpp"

namespace sreh::sizing {

// A spread above this makes the single run's figure misleading (issue 35).
inline constexpr double kChaoticSpread_s = 1e-3;

struct SettlingSpread {
  int counts = 0;       // targets up to this many position counts (360/65536 deg) either side
  int runs = 0;         // the answer's run and the perturbed ones
  int simulations = 0;  // twin runs made (the perturbed ones, and the wider windows tried)
  int incomplete = 0;   // runs with a move that did not complete (left out of the bands)
  std::optional<Band> settling_s, positioning_s; // worst move per completed run
  std::optional<Band> in_window_s;               // worst move per run whose moves all held the window for good
  int moves = 0;        // moves of all runs
  int never_held = 0;   // moves not in the window for good when the next move started
  double tolerance_deg = 0;
  double dwell_s = 0;    // the request's dwell after each move
  double watched_s = 0;  // how much of it is simulated (A-SIZE-9: at most kMaxSimulatedDwell_s)
  // With never_held > 0: the smallest window (2, 4, 8, 16 x the set's) in
  // which every move of every run was held for good; none if not even that.
  std::optional<double> holding_window_deg;
  bool tried_wider = false;
  bool chaotic() const; // settling or in-window time spread above kChaoticSpread_s
};

// `set` (the answer of `request`) run with the target moved by -counts ..
// +counts position counts (`answer` is the run at 0), on `threads` threads.
SettlingSpread settling_spread(const SizingRequest& request, const ParameterSetValues& set, const Evaluation& answer,
                               int counts, int threads);

// `settling_spread` {counts, runs, chaotic, settling_s, positioning_s,
// in_window_s: {lo, p5, median, p95, hi} or null, moves, never_held,
// holding_window_deg, explanation}.
nlohmann::json settling_spread_json(const SettlingSpread& s);
// The text lines of `size`: the spread, and the hunting explanation.
std::string settling_spread_text(const SettlingSpread& s);
// "when the next move started", or "0.2 s after Done (the simulated part of
// the 0.6 s dwell)" where the dwell is longer than what is simulated.
std::string not_held_when(const SettlingSpread& s);
// Why a move may never hold a tight window, in words (text, report, docs/settling.md).
std::string hunting_explanation(const SettlingSpread& s);
// "a 0.0082 deg window was held by every move" (or that none tried was).
std::string holding_window_text(const SettlingSpread& s);

} // namespace sreh::sizing
