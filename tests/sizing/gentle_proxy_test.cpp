// The gentlest search's window (A-SIZE-26, sizing/rms_proxy.hpp) rests on a
// measurement: within one case the simulated RMS torque does not follow the
// plan's (TorqueProxy) exactly, so the search runs every set whose proxy is
// within the window of the best feasible set's. Measured here in the twin
// for a fixed set of cases: every set in the search's order until the proxy
// is twice the window beyond the first feasible set's; the search's rule
// applied to those runs must pick the set of lowest simulated RMS among
// all of them. A change in the twin or the model card that breaks the
// window's basis fails this test (bench/gentle_proxy.py measures it over
// 152 cases; docs/performance-sizing.md).
#include <gtest/gtest.h>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "sizing/rms_proxy.hpp"
#include "sizing/sizing.hpp"

namespace sreh::sizing {
namespace {

struct Case {
  const char* name;
  double angle_deg, load_gcm2, dwell_s, max_positioning_ms;
  double arm_kg = 0, arm_radius_m = 0; // given: an eccentric mass on a horizontal axis instead of the inertia
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

SizingRequest request(const Case& c) {
  SizingRequest rq;
  rq.angle_deg = c.angle_deg;
  if (c.arm_kg > 0) {
    rq.world.load = ArmLoad{c.arm_kg, c.arm_radius_m, 0.0};
    rq.world.mounting_tilt_deg = 90;
  } else {
    rq.world.load = InertiaLoad{c.load_gcm2};
  }
  rq.dwell_s = c.dwell_s;
  rq.max_positioning_ms = c.max_positioning_ms;
  return rq;
}

struct SetRun {
  double proxy_Nm, rms_Nm;
  bool feasible;
};

// The sets in the search's order, run, until the proxy is `reach` beyond
// the first feasible set's (at most 60 runs, the search's own bound).
std::vector<SetRun> runs_within(const SizingRequest& rq, double reach) {
  const double load = validate(rq);
  std::vector<SetRun> runs;
  double first_proxy = -1;
  for (const PlannedSet& p : gentlest_order(rq, load)) {
    if ((first_proxy > 0 && p.rms_proxy_Nm > first_proxy * (1 + reach)) || runs.size() == 60) break;
    const Evaluation ev = evaluate(rq, make_parameter_set(rq, p.setting, load), false);
    runs.push_back({p.rms_proxy_Nm, ev.rms_torque_Nm, ev.feasible});
    if (ev.feasible && first_proxy < 0) first_proxy = p.rms_proxy_Nm;
  }
  return runs;
}

// The search's rule (search.cpp): the best feasible run so far, stopping at
// the first set whose proxy is `window` beyond the best's; its index.
std::optional<std::size_t> searched(const std::vector<SetRun>& runs, double window) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (best && runs[i].proxy_Nm > runs[*best].proxy_Nm * (1 + window)) break;
    if (runs[i].feasible && (!best || runs[i].rms_Nm < runs[*best].rms_Nm)) best = i;
  }
  return best;
}

class Window : public ::testing::TestWithParam<Case> {};

TEST_P(Window, FindsLowestRmsOfTwiceIt) {
  const std::vector<SetRun> runs = runs_within(request(GetParam()), 2 * kGentleProxyWindow);
  std::optional<std::size_t> lowest;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (runs[i].feasible && (!lowest || runs[i].rms_Nm < runs[*lowest].rms_Nm)) lowest = i;
  }
  ASSERT_TRUE(lowest) << "no feasible set: nothing measured";
  // The measurement reaches beyond the window, else it shows nothing.
  ASSERT_GT(runs.back().proxy_Nm, runs[*lowest].proxy_Nm * (1 + kGentleProxyWindow)) << runs.size() << " runs";
  const std::optional<std::size_t> found = searched(runs, kGentleProxyWindow);
  ASSERT_TRUE(found);
  EXPECT_EQ(*found, *lowest) << "RMS " << runs[*found].rms_Nm << " N m found, " << runs[*lowest].rms_Nm
                             << " N m beyond the window; " << runs.size() << " runs";
}

// Those of the 152 cases measured that need the widest window (A-SIZE-26):
// a short move, slow sets chattering while they cruise (1.6 % needed);
// a long dwell, where the torque the friction holds varies from set to
// set (1.1 %); a horizontal eccentric arm, gravity in the proxy (1.1 %).
INSTANTIATE_TEST_SUITE_P(Cases, Window,
                         ::testing::Values(Case{"d15_1000gcm2_100ms", 15, 1000, 0, 100},
                                           Case{"d60_4000gcm2_260ms_dwell", 60, 4000, 0.3, 260},
                                           Case{"arm_horizontal_d10_67ms", 10, 0, 0, 67, 0.311, 0.023}),
                         [](const ::testing::TestParamInfo<Case>& i) { return std::string(i.param.name); });

} // namespace
} // namespace sreh::sizing
