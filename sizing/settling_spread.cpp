#include "sizing/settling_spread.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <fmt/format.h>

#include "device_logic/parameter_ids.hpp"
#include "device_logic/units.hpp"
#include "io/parallel.hpp"
#include "sizing/output.hpp"
#include "sizing/run_parts.hpp"

namespace sreh::sizing {
namespace {

// Windows tried when a move never held the set's (A-SIZE-24).
constexpr double kWiderFactors[] = {2, 4, 8, 16};

// `set` with the target moved by each offset; index `counts` is `answer`.
std::vector<Evaluation> perturbed_runs(const SizingRequest& request, const ParameterSetValues& set,
                                       const Evaluation* answer, int counts, int threads) {
  const std::size_t n = static_cast<std::size_t>(2 * counts + 1);
  std::vector<Evaluation> runs(n);
  io::parallel_for(n, threads, [&](std::size_t i) {
    const int64_t at = deg_to_wire_counts(request.angle_deg);
    const int64_t target = at + static_cast<int64_t>(i) - counts;
    SizingRequest rq = request;
    rq.keep_trace = false;
    // A target on the other side of (or at) the start would be another move: the answer's instead.
    if (target == at || target * at <= 0) rq.angle_deg = wire_counts_to_deg(at);
    else rq.angle_deg = wire_counts_to_deg(target);
    if (target == at && answer != nullptr) {
      runs[i] = *answer;
      runs[i].trace.clear();
      return;
    }
    runs[i] = evaluate(rq, set, false);
  });
  return runs;
}

bool every_move_held(const std::vector<Evaluation>& runs) {
  return std::all_of(runs.begin(), runs.end(), [](const Evaluation& e) {
    return e.completed && std::all_of(e.moves.begin(), e.moves.end(), [](const MoveResult& m) { return m.in_window_s >= 0; });
  });
}

nlohmann::json band_json(const std::optional<Band>& b) {
  if (!b) return nullptr;
  const auto r = [](double v) { return ns_rounded(v); };
  return {{"lo", r(b->lo)}, {"p5", r(b->p5)}, {"median", r(b->median)}, {"p95", r(b->p95)}, {"hi", r(b->hi)}};
}

double spread_s(const std::optional<Band>& b) { return b ? b->hi - b->lo : 0.0; }

} // namespace

bool SettlingSpread::chaotic() const {
  return spread_s(settling_s) > kChaoticSpread_s || spread_s(in_window_s) > kChaoticSpread_s;
}

SettlingSpread settling_spread(const SizingRequest& request, const ParameterSetValues& set, const Evaluation& answer,
                               int counts, int threads) {
  SettlingSpread s;
  s.counts = counts;
  s.tolerance_deg = set.tolerance_deg;
  s.dwell_s = request.dwell_s;
  s.watched_s = std::min(request.dwell_s, kMaxSimulatedDwell_s);
  const std::vector<Evaluation> runs = perturbed_runs(request, set, &answer, counts, threads);
  s.runs = static_cast<int>(runs.size());
  s.simulations = s.runs - 1;
  std::vector<double> settling, positioning, in_window;
  for (const Evaluation& e : runs) {
    if (!e.completed) {
      ++s.incomplete;
      continue;
    }
    settling.push_back(e.settling_s);
    positioning.push_back(e.positioning_s);
    // Per run, like the settling time: its worst move (runs with a move never held left out).
    double worst_in_window = 0;
    bool held = true;
    for (const MoveResult& m : e.moves) {
      ++s.moves;
      if (m.in_window_s >= 0) {
        worst_in_window = std::max(worst_in_window, m.in_window_s);
      } else {
        ++s.never_held;
        held = false;
      }
    }
    if (held) in_window.push_back(worst_in_window);
  }
  if (!settling.empty()) {
    s.settling_s = band_of(settling);
    s.positioning_s = band_of(positioning);
  }
  if (!in_window.empty()) s.in_window_s = band_of(in_window);
  if (s.never_held > 0) {
    // Which window holds: the same runs with a wider window (A-SIZE-24).
    s.tried_wider = true;
    const double max_tolerance_deg = display_max(param::MotionSet(0).tolerance);
    for (double f : kWiderFactors) {
      SizingRequest rq = request;
      rq.settling.tolerance_deg = std::min(max_tolerance_deg, f * set.tolerance_deg);
      const ParameterSetValues wider = make_parameter_set(rq, set.setting, set.load_gcm2);
      s.simulations += s.runs;
      if (every_move_held(perturbed_runs(rq, wider, nullptr, counts, threads))) {
        s.holding_window_deg = wider.tolerance_deg;
        break;
      }
      if (rq.settling.tolerance_deg >= max_tolerance_deg) break;
    }
  }
  return s;
}

std::string not_held_when(const SettlingSpread& s) {
  if (s.dwell_s <= s.watched_s) return "when the next move started";
  return fmt::format("{:g} s after Done (the simulated part of the {:g} s dwell)", s.watched_s, s.dwell_s);
}

std::string hunting_explanation(const SettlingSpread& s) {
  return fmt::format(
      "hunting at the window's edge: near the target the drive's torque is below the rotor's breakaway friction "
      "(Coulomb friction plus the Stribeck rise at standstill), so the rotor sticks a few counts off; the velocity "
      "loop's integral winds up until it breaks loose, and because sliding friction is lower than breakaway the "
      "rotor jumps on past; the encoder sees whole counts only (2^19 per revolution, {:.5f} deg), so the loop cannot "
      "see an error below a count. The stick-slip cycle's amplitude is a few counts: a window that narrow ({:.4f} deg) "
      "is entered and left again",
      360.0 / 524288.0, s.tolerance_deg);
}

nlohmann::json settling_spread_json(const SettlingSpread& s) {
  return {{"counts", s.counts},
          {"runs", s.runs},
          {"incomplete_runs", s.incomplete},
          {"chaotic", s.chaotic()},
          {"settling_s", band_json(s.settling_s)},
          {"positioning_s", band_json(s.positioning_s)},
          {"in_window_s", band_json(s.in_window_s)},
          {"moves", s.moves},
          {"never_held", s.never_held},
          {"tolerance_deg", s.tolerance_deg},
          {"holding_window_deg", optional_number(s.holding_window_deg)},
          {"explanation", s.never_held > 0 ? nlohmann::json(hunting_explanation(s)) : nlohmann::json()}};
}

std::string holding_window_text(const SettlingSpread& s) {
  return s.holding_window_deg ? fmt::format("a {:.4f} deg window was held by every move", *s.holding_window_deg)
                              : fmt::format("not even a window {:.0f} times as wide was held by every move",
                                            kWiderFactors[std::size(kWiderFactors) - 1]);
}

std::string settling_spread_text(const SettlingSpread& s) {
  const std::string over = fmt::format("over targets -{0} .. +{0} counts ({1} runs{2})", s.counts, s.runs,
                                       s.incomplete ? fmt::format(", {} not completed", s.incomplete) : "");
  std::string o;
  if (!s.settling_s) {
    o = fmt::format("  settling spread   none: no run {} completed\n", over);
  } else if (!s.chaotic()) {
    o = fmt::format("  settling spread   within {:.1f} ms {}: the figures above hold\n",
                    1e3 * std::max(spread_s(s.settling_s), spread_s(s.in_window_s)), over);
  } else {
    o = fmt::format("  settling spread   {}: settling median {:.4f} s, p95 {:.4f} s (min .. max {:.4f} .. {:.4f} s), "
                    "positioning median {:.4f} s, p95 {:.4f} s; the single run above is one draw of these\n",
                    over, s.settling_s->median, s.settling_s->p95, s.settling_s->lo, s.settling_s->hi,
                    s.positioning_s->median, s.positioning_s->p95);
    if (s.in_window_s) {
      o += fmt::format("  into the window   for good: median {:.4f} s, p95 {:.4f} s (min .. max {:.4f} .. {:.4f} s) from the end "
                       "of the trajectory, worst move per run\n",
                       s.in_window_s->median, s.in_window_s->p95, s.in_window_s->lo, s.in_window_s->hi);
    }
  }
  if (s.never_held > 0) {
    o += fmt::format("  window not held   {} of {} moves were outside the {:.4f} deg window {}: {}; ",
                     s.never_held, s.moves, s.tolerance_deg, not_held_when(s), hunting_explanation(s));
    o += holding_window_text(s) + "\n";
  }
  return o;
}

} // namespace sreh::sizing
