// Sweeps (issue 8): grid order, determinism over thread counts, the
// inverse "heaviest load for a target time".
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>

#include "sizing/sweep.hpp"

namespace sreh::sizing {
namespace {

std::string csv_of(const SweepResult& r) {
  std::ostringstream out;
  write_sweep_csv(out, r);
  return out.str();
}

SweepRequest small_grid() {
  SweepRequest rq;
  rq.loads_gcm2 = {0.0, 6000.0};
  rq.angles_deg = {20.0, 60.0};
  rq.voltages_V = {24.0};
  rq.base.cycles = 1;
  return rq;
}

TEST(Sweep, GridOrderLoadsOutermost) {
  SweepRequest rq = small_grid();
  rq.voltages_V = {20.0, 24.0};
  rq.speeds_dps = {1000.0};
  const std::vector<SizingRequest> g = sweep_requests(rq);
  ASSERT_EQ(g.size(), 8u);
  EXPECT_EQ(std::get<InertiaLoad>(g[0].world.load).inertia_gcm2, 0.0);
  EXPECT_EQ(g[0].angle_deg, 20.0);
  EXPECT_EQ(g[0].world.supply.voltage_V, 20.0);
  EXPECT_EQ(g[1].world.supply.voltage_V, 24.0);
  EXPECT_EQ(g[2].angle_deg, 60.0);
  EXPECT_EQ(std::get<InertiaLoad>(g[4].world.load).inertia_gcm2, 6000.0);
  ASSERT_TRUE(g[0].setting.has_value());
  EXPECT_EQ(g[0].setting->speed_dps, 1000.0);
}

TEST(Sweep, RefusesBadAxes_6_2) {
  SweepRequest rq = small_grid();
  rq.loads_gcm2 = {};
  EXPECT_THROW(sweep_requests(rq), SizingInputError);
  rq = small_grid();
  rq.voltages_V = {24.0, 40.0};
  EXPECT_THROW(run_sweep(rq), SizingInputError); // before any point runs
}

// Each thread its own twin; results in grid order: the CSV is identical for
// one and two threads (recommendations included).
TEST(Sweep, DeterministicForOneOrTwoThreads) {
  SweepRequest rq = small_grid();
  rq.threads = 1;
  const std::string one = csv_of(run_sweep(rq));
  rq.threads = 2;
  const std::string two = csv_of(run_sweep(rq));
  EXPECT_EQ(one, two);
  EXPECT_EQ(std::count(one.begin(), one.end(), '\n'), 5); // header + 4 points
  EXPECT_EQ(one.rfind("load_gcm2,angle_deg,voltage_V,mode,", 0), 0u);
}

SweepPoint point(double load, double angle, double positioning, bool feasible) {
  SweepPoint p;
  p.load_gcm2 = load;
  p.angle_deg = angle;
  p.voltage_V = 24.0;
  p.result.evaluation.positioning_s = positioning;
  p.result.evaluation.feasible = feasible;
  p.result.evaluation.completed = true;
  return p;
}

TEST(Sweep, HeaviestLoadMeetingATargetTime) {
  SweepResult r;
  r.points = {point(1000, 90, 0.10, true), point(5000, 90, 0.15, true), point(10000, 90, 0.20, true),
              point(15000, 90, 0.18, false), // faster but infeasible: never counts
              point(1000, 180, 0.16, true), point(5000, 180, 0.25, true)};
  const std::vector<SweepGroup> groups = sweep_groups(r);
  ASSERT_EQ(groups.size(), 1u);
  const std::vector<HeaviestLoad> h = heaviest_loads(r, groups[0], {0.05, 0.15, 0.30});
  ASSERT_EQ(h.size(), 6u); // 2 angles x 3 targets
  EXPECT_FALSE(h[0].load_gcm2.has_value());
  EXPECT_EQ(h[1].load_gcm2, 5000.0); // 0.15 s met exactly
  EXPECT_EQ(h[2].load_gcm2, 10000.0);
  EXPECT_EQ(h[3].angle_deg, 180.0);
  EXPECT_FALSE(h[4].load_gcm2.has_value());
  EXPECT_EQ(h[5].load_gcm2, 5000.0);
}

} // namespace
} // namespace sreh::sizing
