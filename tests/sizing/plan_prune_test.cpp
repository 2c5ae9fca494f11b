// The gentlest search (sizing/search.cpp, A-SIZE-10) drops every set whose
// planned travel plus the waiting time already misses the target, without
// running it: positioning = planned travel + settling (manual 3.5.2 (4)),
// and Done needs the set's waiting time in the window after the trajectory
// ends (3.5.2 (2), (f)), so settling >= waiting time. If that bound were
// wrong, the prune would drop sets that meet the target and the search
// could miss the gentlest one. Checked in the twin: the sets just beyond the
// bound (the first a wrong bound would drop wrongly) fail the target when
// run, and every run of a search positions no earlier than the bound says.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "device_logic/planner.hpp"
#include "device_logic/units.hpp"
#include "sizing/sizing.hpp"

namespace sreh::sizing {
namespace {

struct PruneCase {
  const char* name;
  double angle_deg, load_gcm2, dwell_s;
  double max_positioning_ms; // 0: none
  double max_cycle_ms;       // 0: none
};

SizingRequest prune_request(const PruneCase& c) {
  SizingRequest rq;
  rq.angle_deg = c.angle_deg;
  rq.world.load = InertiaLoad{c.load_gcm2};
  rq.dwell_s = c.dwell_s;
  rq.cycles = 1;
  if (c.max_positioning_ms > 0) rq.max_positioning_ms = c.max_positioning_ms;
  if (c.max_cycle_ms > 0) rq.max_cycle_ms = c.max_cycle_ms;
  return rq;
}

// The worst positioning time the target allows, as the search derives it.
double allowed_positioning_s(const SizingRequest& rq) {
  double s = rq.max_positioning_ms ? *rq.max_positioning_ms * 1e-3 : 1e9;
  if (rq.max_cycle_ms) {
    s = std::min(s, (*rq.max_cycle_ms * 1e-3 - 2.0 * rq.dwell_s) / 2.0 - rq.handshake_cycles * TwinConfig{}.cycle_s);
  }
  return s;
}

double prune_travel_s(const SizingRequest& rq, const MotionSetting& s, double load_gcm2) {
  const double d = internal_counts_to_rad(deg_to_wire_counts(rq.angle_deg) * kInternalPerWireCount);
  return Profile::rest_to_rest(d, limits_from_parameter_set(s.speed_dps, s.accel_pct, s.jerk_pct, load_gcm2))
      .duration_s();
}

struct Beyond {
  MotionSetting setting;
  double bound_s; // planned travel + waiting time
};

// Sets the prune drops, nearest the bound first: a grid of its own (not the
// search's levels), speeds in 0.1 deg/s as the device stores them.
std::vector<Beyond> just_beyond(const SizingRequest& rq, double load_gcm2, double wait_s, std::size_t n) {
  const double v_top = voltage_speed_limit_dps(rq.world.supply.voltage_V);
  const double allowed = allowed_positioning_s(rq);
  std::vector<Beyond> out;
  for (double v = 0.04; v <= 1.0; v *= 1.09) {
    for (double a = 3.0; a <= 100.0; a *= 1.17) {
      for (double j : {5.0, 12.0, 30.0, 70.0, 100.0}) {
        const MotionSetting s{std::round(v_top * v * 10.0) / 10.0, std::round(a * 10.0) / 10.0, j};
        const double bound = prune_travel_s(rq, s, load_gcm2) + wait_s;
        if (bound > allowed && bound <= allowed + 0.004) out.push_back({s, bound});
      }
    }
  }
  std::sort(out.begin(), out.end(), [](const Beyond& x, const Beyond& y) { return x.bound_s < y.bound_s; });
  if (out.size() > n) out.resize(n);
  return out;
}

class PlanPrune : public ::testing::TestWithParam<PruneCase> {};

TEST_P(PlanPrune, BeyondBoundMisses_3_5_2) {
  const SizingRequest rq = prune_request(GetParam());
  const double load_gcm2 = validate(rq);
  const double wait_s = make_parameter_set(rq, MotionSetting{}, load_gcm2).wait_ms * 1e-3;
  const double allowed = allowed_positioning_s(rq);
  const std::vector<Beyond> sets = just_beyond(rq, load_gcm2, wait_s, 4);
  ASSERT_GE(sets.size(), 2u) << "no set within 4 ms beyond the bound: the case checks nothing";
  for (const Beyond& b : sets) {
    SizingRequest one = rq;
    one.setting = b.setting;
    const SizingResult r = size(one);
    const std::string what = std::to_string(b.setting.speed_dps) + " deg/s " + std::to_string(b.setting.accel_pct) +
                             " % " + std::to_string(b.setting.jerk_pct) + " %";
    EXPECT_FALSE(r.feasible) << what << " meets the target the prune dropped it for";
    if (r.evaluation.completed) {
      EXPECT_GT(r.evaluation.positioning_s, allowed) << what;
      EXPECT_GE(r.evaluation.positioning_s, b.bound_s - 1e-12) << what;
    }
  }
}

// Every run the search made (kept in `tried`) positions no earlier than its
// planned travel plus the waiting time: the bound holds for the sets the
// search did run, feasible or not.
TEST_P(PlanPrune, RunsMeetBound_3_5_2) {
  const SizingRequest rq = prune_request(GetParam());
  const SizingResult r = size(rq);
  ASSERT_EQ(r.objective, "gentlest");
  ASSERT_FALSE(r.tried.empty());
  int completed = 0;
  for (const Evaluation& e : r.tried) {
    if (!e.completed) continue;
    ++completed;
    EXPECT_GE(e.positioning_s, e.travel_s + e.set.wait_ms * 1e-3 - 1e-12)
        << e.set.setting.speed_dps << " deg/s " << e.set.setting.accel_pct << " % " << e.set.setting.jerk_pct << " %";
  }
  EXPECT_GT(completed, 0);
}

INSTANTIATE_TEST_SUITE_P(Cases, PlanPrune,
                         ::testing::Values(PruneCase{"m90_5000g_300ms", 90.0, 5000.0, 0.0, 300.0, 0.0},
                                           PruneCase{"m60_4000g_260ms", 60.0, 4000.0, 0.3, 260.0, 0.0},
                                           PruneCase{"m45_8000g_250ms", 45.0, 8000.0, 0.0, 250.0, 0.0},
                                           PruneCase{"c120_3000g_900ms", 120.0, 3000.0, 0.1, 0.0, 900.0}),
                         [](const ::testing::TestParamInfo<PruneCase>& p) { return std::string(p.param.name); });

} // namespace
} // namespace sreh::sizing
