// The gentlest search's window (A-SIZE-27, sizing/rms_proxy.hpp) rests on a
// measurement: within one case, the simulated RMS torque over the plan's
// (TorqueProxy) varies so little that a set whose proxy is more than the
// window beyond the best set's cannot have a lower simulated RMS. With r =
// simulated / proxy, that holds while r(best) / r(set) - 1 stays below the
// window for every feasible set. Measured here in the twin for a fixed set
// of cases (every set the search considers, in its order, until the proxy
// is a window beyond the first feasible set's), so a change in the twin or
// the model card that breaks the window's basis fails this test
// (bench/gentle_proxy.py measures it over 152 cases).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "sizing/rms_proxy.hpp"
#include "sizing/sizing.hpp"

namespace sreh::sizing {
namespace {

struct Case {
  const char* name;
  double angle_deg, load_gcm2, dwell_s, max_positioning_ms, tilt_deg;
  bool arm; // an eccentric arm (0.3 kg at 60 mm) instead of an inertia on the axis
};

SizingRequest request(const Case& c) {
  SizingRequest rq;
  rq.angle_deg = c.angle_deg;
  if (c.arm) rq.world.load = ArmLoad{0.3, 0.06, 0.0};
  else rq.world.load = InertiaLoad{c.load_gcm2};
  rq.dwell_s = c.dwell_s;
  rq.max_positioning_ms = c.max_positioning_ms;
  rq.world.mounting_tilt_deg = c.tilt_deg;
  return rq;
}

struct Measured {
  double needed = 0;  // max over feasible sets of r(best) / r(set) - 1
  int runs = 0, feasible = 0;
};

Measured measure(const SizingRequest& rq) {
  const double load = validate(rq);
  const std::vector<PlannedSet> order = gentlest_order(rq, load);
  struct Run { double proxy, rms; };
  std::vector<Run> feasible;
  Measured m;
  double first_proxy = -1;
  for (const PlannedSet& p : order) {
    if (first_proxy > 0 && p.rms_proxy_Nm > first_proxy * (1 + kGentleProxyWindow)) break;
    if (m.runs == 60) break; // the search's own bound
    const Evaluation ev = evaluate(rq, make_parameter_set(rq, p.setting, load), false);
    ++m.runs;
    if (!ev.feasible) continue;
    if (first_proxy < 0) first_proxy = p.rms_proxy_Nm;
    feasible.push_back({p.rms_proxy_Nm, ev.rms_torque_Nm});
  }
  m.feasible = static_cast<int>(feasible.size());
  if (feasible.empty()) return m;
  const Run best = *std::min_element(feasible.begin(), feasible.end(),
                                     [](const Run& a, const Run& b) { return a.rms < b.rms; });
  for (const Run& f : feasible) m.needed = std::max(m.needed, (best.rms / best.proxy) / (f.rms / f.proxy) - 1.0);
  return m;
}

class Window : public ::testing::TestWithParam<Case> {};

TEST_P(Window, HoldsTheProxysMeasuredError) {
  const Measured m = measure(request(GetParam()));
  ASSERT_GE(m.feasible, 5) << "too few feasible sets to measure";
  EXPECT_LT(m.needed, kGentleProxyWindow) << m.runs << " runs, " << m.feasible << " feasible";
}

// From docs/performance-sizing.md's twelve gentlest cases: the one with the
// widest need, a long dwell (the hold torque left by the friction), and a
// horizontal eccentric arm (gravity in the proxy).
INSTANTIATE_TEST_SUITE_P(Cases, Window,
                         ::testing::Values(Case{"deg45_8000_250ms", 45, 8000, 0, 250, 0, false},
                                           Case{"deg60_4000_260ms_dwell", 60, 4000, 0.3, 260, 0, false},
                                           Case{"arm_horizontal_90deg_300ms", 90, 0, 0, 300, 90, true}),
                         [](const ::testing::TestParamInfo<Case>& i) { return std::string(i.param.name); });

} // namespace
} // namespace sreh::sizing
