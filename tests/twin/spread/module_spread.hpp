// Shared by the module spread tests (issue 35): a module of the card with
// some constants changed, and one run of it: Motor On, hold, rated moves,
// hold, with the figures the tests judge.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "twin/model_card.hpp"
#include "twin/specs.hpp"

namespace sreh::test {

// The card with `values` (name, value) put in; the names must be the card's.
ModuleModel module_with(const std::vector<std::pair<std::string, double>>& values);

// What the spread test runs a module in (docs/model-card.md "Ranges").
enum class Mounting { VerticalEmpty, VerticalRatedDisk, HorizontalRatedArm };
const char* mounting_name(Mounting m);

struct HoldFigures {
  double torque_peak_to_peak_Nm = 0; // commanded motor torque, sampled each 2 ms master cycle
  double position_band_deg = 0;      // encoder, max - min
};

struct SpreadRun {
  bool ready = false;                // Ready after Motor On
  HoldFigures after_motor_on;        // 0.1 .. 0.3 s after Ready
  HoldFigures after_moves;           // 0.1 .. 0.3 s after the last move's Done
  int moves_completed = 0;           // of 3 (to 90, -90 and 0 deg)
  double max_settling_s = 0;         // of the completed moves (manual 3.5.2 (2))
  uint8_t error_code = 0;            // manual 2.4 bit field of the first error (0: none)
};

// One module in one mounting: Motor On with set 1 selected and configured
// for the load, hold, to 90, -90 and 0 deg at 3000 deg/s with the mounting's
// rated acceleration (100 % vertical, 50 % for the horizontal arm,
// A-TWIN-24) and the factory window, waiting time and settling timeout.
SpreadRun run_module(const ModuleModel& module, Mounting mounting);

// Deterministic Latin-hypercube samples of every card constant whose range
// is wider than a point: sample i gives constant c the value
// lo + (perm_c[i] + u) / n (hi - lo), whole numbers rounded.
std::vector<std::vector<std::pair<std::string, double>>> latin_hypercube(int n, uint64_t seed);

} // namespace sreh::test
