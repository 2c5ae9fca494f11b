// Which move of the identification program shows which constant (issue 36:
// "`calibrate --plan` prints which segment identifies which constant", A-CAL-13).
// Measured, not declared: the plan is run on the card and its master log
// replayed once with the card and once per constant moved 10 % inside its
// range; the twin's position change, row by row, is shared out over the
// plan's moves (a move: its command and the hold after it). A constant whose
// change does not rise above the replay's own jitter (the same replay with
// a constant 0.1 % off) barely shows in the log. It says what the
// plan excites at this load on this card; whether a fit can separate two
// constants that show in the same moves is the fit's correlation matrix.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "scenarios/scenario.hpp"
#include "twin/model_card.hpp"

namespace sreh {

struct LoggedMove {
  int parameter_set = 0;
  double target_deg = 0;
  double t0_s = 0, t1_s = 0; // the log's rows of the move and its hold
};

struct ConstantSensitivity {
  std::string name;
  double step_relative = 0;     // +0.10, or -0.10 where +10 % leaves the range
  double rms_change_counts = 0; // the twin's position change over the whole log, wire counts
  double peak_change_counts = 0;
  // Per plan move (PlanSensitivity::moves' order): its share of the change's
  // sum of squares, 0..1.
  std::vector<double> share;
  // The change is at least twice the jitter's rms and a count somewhere.
  bool shows = false;
};

struct PlanSensitivity {
  std::vector<LoggedMove> moves;
  std::vector<ConstantSensitivity> constants;
  // The replay's own jitter: the first named constant moved by 0.1 %. With a
  // quantised encoder in the loop any change flips a count somewhere, and
  // that carries on; what a constant changes must rise above it.
  ConstantSensitivity jitter;
};

// `plan` as calibration_plan_yaml writes it (any scenario with moves will
// do); `names` are card constants with a range. Replays run on `threads`.
PlanSensitivity plan_sensitivity(const Scenario& plan, const ModelCard& card, const std::vector<std::string>& names,
                                 int threads);

// The table `calibrate --plan` prints: per constant its change and the
// moves that hold most of it.
std::string format_plan_sensitivity(const PlanSensitivity& s);

} // namespace sreh
