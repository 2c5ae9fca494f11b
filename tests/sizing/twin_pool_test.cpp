// Issue 31: sizing runs take their twin from a pool, restored to its state
// right after construction (sizing/twin_factory.hpp); issue 37: one pool for
// all threads (the searches' look-ahead runs each come on a new thread). A
// run must not see what the run before it did, on this thread or another:
// the same request evaluated first, after a run in another world, after a
// run in the same world and on another thread gives the same figures and
// the same trace, bit for bit.
#include <gtest/gtest.h>

#include <string>
#include <thread>

#include "sizing/output.hpp"
#include "sizing/sizing.hpp"

namespace sreh::sizing {
namespace {

// A world no other test of this executable builds: the first run's twin is
// built, not taken from the pool.
constexpr double kLoad_gcm2 = 6123.25;

SizingRequest request(double angle_deg, double load_gcm2, double voltage_V) {
  SizingRequest rq;
  rq.angle_deg = angle_deg;
  rq.world.load = InertiaLoad{load_gcm2};
  rq.world.supply.voltage_V = voltage_V;
  rq.cycles = 1;
  return rq;
}

// What `size --json` prints for an evaluation.
std::string json_of(const SizingRequest& rq, const Evaluation& e) {
  SizingResult r;
  r.evaluation = e;
  r.feasible = e.feasible;
  return to_json(rq, r).dump();
}

void expect_same(const Evaluation& a, const Evaluation& b) {
  EXPECT_EQ(json_of(request(120, kLoad_gcm2, 24), a), json_of(request(120, kLoad_gcm2, 24), b));
  ASSERT_EQ(a.trace.size(), b.trace.size());
  for (std::size_t r = 0; r < a.trace.size(); ++r) {
    ASSERT_EQ(a.trace[r].position_deg, b.trace[r].position_deg) << r;
    ASSERT_EQ(a.trace[r].torque_Nm, b.trace[r].torque_Nm) << r;
    ASSERT_EQ(a.trace[r].temperature_C, b.trace[r].temperature_C) << r;
    ASSERT_EQ(a.trace[r].pd_in, b.trace[r].pd_in) << r;
  }
  EXPECT_EQ(a.sim_time_s, b.sim_time_s);
}

TEST(TwinPool, ARunDoesNotSeeTheRunsBeforeIt) {
  const SizingRequest rq = request(120, kLoad_gcm2, 24);
  const SizingRequest other = request(45, 12000, 20);
  const MotionSetting fast{3000, 80, 80}, slow{800, 30, 30};
  const ParameterSetValues set = make_parameter_set(rq, fast, kLoad_gcm2);
  Evaluation first;
  std::thread([&] { first = evaluate(rq, set, true); }).join(); // built
  ASSERT_TRUE(first.completed);
  expect_same(first, evaluate(rq, set, true)); // restored on another thread than it was built on
  Evaluation again;
  std::thread([&] { again = evaluate(rq, set, true); }).join(); // and on a third
  expect_same(first, again);
  (void)evaluate(rq, make_parameter_set(rq, slow, kLoad_gcm2), true);    // same world, another set
  expect_same(first, evaluate(rq, set, true));
  (void)evaluate(other, make_parameter_set(other, fast, 12000), false);  // another world in between
  expect_same(first, evaluate(rq, set, true));
}

} // namespace
} // namespace sreh::sizing
