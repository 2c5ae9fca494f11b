#include "calibration/plan_sensitivity.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <fmt/format.h>

#include "calibration/fit_adequacy.hpp"
#include "calibration/replay.hpp"
#include "io/parallel.hpp"

namespace sreh {
namespace {

constexpr double kStepRelative = 0.10;
// The replay's own jitter: the first constant moved by this little. A
// quantised encoder in the loop turns any change into a count flipped
// somewhere, which carries on (measured: a 1 % and a 10 % change of a
// friction constant move the position alike, ~0.2 counts rms at
// 15000 g cm^2); a constant must rise above it to show.
constexpr double kJitterStepRelative = 0.001;
constexpr double kShowsAboveJitter = 2.0;
// Moves listed per constant: the largest shares until they hold this much.
constexpr double kListedShare = 0.75;
constexpr std::size_t kMaxListed = 3;

// The card with `name` moved by `relative` of its value, up unless that
// leaves the range, else down, else to the farther bound of a narrow range;
// the step taken.
double moved(ModelCard& card, const std::string& name, double relative) {
  for (ModelConstant& c : card.constants) {
    if (c.name != name) continue;
    double step = relative;
    if (c.value * (1 + relative) > c.range_hi) {
      step = c.value * (1 - relative) >= c.range_lo ? -relative
             : c.range_hi - c.value >= c.value - c.range_lo ? c.range_hi / c.value - 1
                                                            : c.range_lo / c.value - 1;
    }
    c.value *= 1 + step;
    return step;
  }
  throw std::invalid_argument("plan_sensitivity: no constant " + name + " on the card");
}

} // namespace

PlanSensitivity plan_sensitivity(const Scenario& plan, const ModelCard& card, const std::vector<std::string>& names,
                                 int threads) {
  if (names.empty()) throw std::invalid_argument("plan_sensitivity: no constants named");
  const MasterLog log = record_master_log(plan, card.module_model());
  const ReplaySetup setup = replay_setup(log, plan.world.load, &plan);

  // A move: the rows from its Move edge (manual 2.2) to the next one.
  PlanSensitivity result;
  std::vector<int> move_of_row(log.rows.size(), -1);
  bool moving = false;
  for (std::size_t k = 0; k < log.rows.size(); ++k) {
    const ProcessDataOut out = decode_out(log.rows[k].pd_out);
    if (out.move && !moving) {
      result.moves.push_back({out.parameter_set, out.target_raw * kWireCount_deg, log.rows[k].t_s, log.rows[k].t_s});
    }
    moving = out.move;
    if (!result.moves.empty()) {
      move_of_row[k] = static_cast<int>(result.moves.size()) - 1;
      result.moves.back().t1_s = log.rows[k].t_s;
    }
  }

  // Replay 0 with the card, replay 1 with names[0] moved by the jitter's
  // step, replay i + 2 with names[i] moved.
  std::vector<ReplayTrack> tracks(names.size() + 2);
  result.constants.resize(names.size() + 1);
  io::parallel_for(tracks.size(), threads, [&](std::size_t i) {
    ModelCard c = card;
    if (i > 0) {
      ConstantSensitivity& s = result.constants[i - 1];
      s.name = i == 1 ? names[0] : names[i - 2];
      s.step_relative = moved(c, s.name, i == 1 ? kJitterStepRelative : kStepRelative);
    }
    tracks[i] = replay(setup, c.module_model(), log);
  });

  const std::vector<double>& base = tracks[0].position_deg;
  for (std::size_t i = 0; i < result.constants.size(); ++i) {
    ConstantSensitivity& s = result.constants[i];
    s.share.assign(result.moves.size(), 0.0);
    double total = 0;
    for (std::size_t k = 0; k < base.size(); ++k) {
      const double d = (tracks[i + 1].position_deg[k] - base[k]) / kWireCount_deg;
      total += d * d;
      s.peak_change_counts = std::max(s.peak_change_counts, std::abs(d));
      if (move_of_row[k] >= 0) s.share[static_cast<std::size_t>(move_of_row[k])] += d * d;
    }
    s.rms_change_counts = std::sqrt(total / static_cast<double>(std::max<std::size_t>(base.size(), 1)));
    if (total > 0) {
      for (double& share : s.share) share /= total;
    }
  }
  result.jitter = result.constants.front();
  result.constants.erase(result.constants.begin());
  for (ConstantSensitivity& s : result.constants) {
    s.shows = s.rms_change_counts >= kShowsAboveJitter * result.jitter.rms_change_counts && s.peak_change_counts >= 1;
  }
  return result;
}

std::string format_plan_sensitivity(const PlanSensitivity& s) {
  std::string out = fmt::format(
      "Which moves of the plan show which constant: the plan run on the card and replayed with each constant "
      "10 % up (down, or less, where that leaves its range); the change of the twin's position, wire counts.\n"
      "  {:<22} rms {:5.2f}, peak {:5.1f} counts: the replay's own jitter ({} {:g} % up: a count flipped in the "
      "loop carries on); a constant shows where it rises to twice this\n",
      "jitter", s.jitter.rms_change_counts, s.jitter.peak_change_counts, s.jitter.name, 100 * s.jitter.step_relative);
  for (const ConstantSensitivity& c : s.constants) {
    out += fmt::format("  {:<22} rms {:5.2f}, peak {:5.1f} counts", c.name, c.rms_change_counts, c.peak_change_counts);
    if (std::abs(c.step_relative - kStepRelative) > 1e-9) out += fmt::format(" ({:+.1f} %)", 100 * c.step_relative);
    if (!c.shows) {
      out += ": within the jitter, the log hardly tells it\n";
      continue;
    }
    std::vector<std::size_t> order(c.share.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return c.share[a] > c.share[b]; });
    double listed = 0;
    std::string sep = ": ";
    for (std::size_t n = 0; n < order.size() && n < kMaxListed && listed < kListedShare; ++n) {
      const LoggedMove& m = s.moves[order[n]];
      out += fmt::format("{}move {} (to {:g} deg, set {}, {:.2f}..{:.2f} s) {:.0f} %", sep, order[n] + 1,
                         std::round(m.target_deg * 100) / 100, m.parameter_set, m.t0_s, m.t1_s, 100 * c.share[order[n]]);
      listed += c.share[order[n]];
      sep = ", ";
    }
    out += "\n";
  }
  return out;
}

} // namespace sreh
