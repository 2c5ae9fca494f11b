// Issue 31: sizing runs take their twin from a per-thread pool, restored to
// its state right after construction (sizing/twin_factory.hpp). A run must
// not see what the run before it did: the same request evaluated first, after
// a run in another world and after a run in the same world gives the same
// figures and the same trace, bit for bit.
#include <gtest/gtest.h>

#include <string>
#include <thread>

#include "sizing/output.hpp"
#include "sizing/sizing.hpp"

namespace sreh::sizing {
namespace {

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
  EXPECT_EQ(json_of(request(120, 6000, 24), a), json_of(request(120, 6000, 24), b));
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
  const SizingRequest rq = request(120, 6000, 24);
  const SizingRequest other = request(45, 12000, 20);
  const MotionSetting fast{3000, 80, 80}, slow{800, 30, 30};
  const ParameterSetValues set = make_parameter_set(rq, fast, 6000);
  Evaluation first;
  // A fresh thread: its pool is empty, so this twin is built, not restored.
  std::thread([&] { first = evaluate(rq, set, true); }).join();
  ASSERT_TRUE(first.completed);
  expect_same(first, evaluate(rq, set, true));                          // restored
  (void)evaluate(rq, make_parameter_set(rq, slow, 6000), true);          // same world, another set
  expect_same(first, evaluate(rq, set, true));
  (void)evaluate(other, make_parameter_set(other, fast, 12000), false);  // another world in between
  expect_same(first, evaluate(rq, set, true));
}

} // namespace
} // namespace sreh::sizing
