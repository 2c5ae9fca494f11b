// Planner cost (manual 3.5): one rest-to-rest plan, one stop plan, one
// sample. Inputs are drawn from a fixed-seed pool so the branch mix is
// varied (all cases of the closed form) but the run is repeatable.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "device_logic/planner.hpp"
#include "device_logic/position_controller.hpp"
#include "device_logic/units.hpp"

namespace {

using sreh::KinematicState;
using sreh::MotionLimits;
using sreh::Profile;

constexpr std::size_t kPool = 4096; // power of two: index with a mask

struct Move {
  double distance_rad;
  MotionLimits limits;
};

const std::vector<Move>& moves() {
  static const std::vector<Move> pool = [] {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> speed(0.1, 4300.0), pct(0.1, 100.0), load(0.0, 15000.0);
    std::uniform_real_distribution<double> log_dist(-5.0, 3.0);
    std::bernoulli_distribution neg(0.5);
    std::vector<Move> v;
    for (std::size_t i = 0; i < kPool; ++i) {
      const double d = std::pow(10.0, log_dist(rng));
      v.push_back({neg(rng) ? -d : d, sreh::limits_from_parameter_set(speed(rng), pct(rng), pct(rng), load(rng))});
    }
    return v;
  }();
  return pool;
}

void BM_RestToRestPlan(benchmark::State& state) {
  const auto& pool = moves();
  std::size_t i = 0;
  for (auto _ : state) {
    const Move& m = pool[i++ & (kPool - 1)];
    Profile p = Profile::rest_to_rest(m.distance_rad, m.limits);
    benchmark::DoNotOptimize(p);
  }
}
BENCHMARK(BM_RestToRestPlan);

void BM_StopPlan(benchmark::State& state) {
  const auto& pool = moves();
  std::vector<KinematicState> from;
  std::mt19937_64 rng(43);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const Move& m : pool) from.push_back({0.0, u(rng) * m.limits.v_max_rad_s, u(rng) * m.limits.a_max_rad_s2, 0.0});
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ & (kPool - 1);
    Profile p = Profile::stop(from[k], pool[k].limits);
    benchmark::DoNotOptimize(p);
  }
}
BENCHMARK(BM_StopPlan);

// One control-step sample at(t), the device's per-step cost; t walks through
// the profile at the 0.1 ms control step so every phase is visited.
void BM_Sample(benchmark::State& state) {
  const Profile p = Profile::rest_to_rest(sreh::deg_to_rad(360.0), sreh::limits_from_parameter_set(3000, 100, 100, 2000));
  const double dt = 1e-4;
  double t = 0;
  for (auto _ : state) {
    KinematicState s = p.at(t);
    benchmark::DoNotOptimize(s);
    t += dt;
    if (t > p.duration_s()) t = 0;
  }
}
BENCHMARK(BM_Sample);

// Samples at random times (phase lookup branch mispredicted).
void BM_SampleRandomTime(benchmark::State& state) {
  const Profile p = Profile::rest_to_rest(sreh::deg_to_rad(360.0), sreh::limits_from_parameter_set(3000, 100, 100, 2000));
  std::mt19937_64 rng(44);
  std::uniform_real_distribution<double> u(0.0, p.duration_s());
  std::vector<double> ts(kPool);
  for (double& t : ts) t = u(rng);
  std::size_t i = 0;
  for (auto _ : state) {
    KinematicState s = p.at(ts[i++ & (kPool - 1)]);
    benchmark::DoNotOptimize(s);
  }
}
BENCHMARK(BM_SampleRandomTime);

// One position-controller step (the other per-step cost of the device),
// following a profile through a perfect plant so all terms are live.
void BM_ControllerUpdate(benchmark::State& state) {
  const Profile p = Profile::rest_to_rest(sreh::deg_to_rad(360.0), sreh::limits_from_parameter_set(3000, 100, 100, 2000));
  sreh::PositionController c;
  c.reset(0.0);
  const double dt = 1e-4;
  double t = 0;
  for (auto _ : state) {
    const KinematicState s = p.at(t);
    double torque = c.update(s, s.pos_rad * 0.999, 3.15e-4, 0.6, 0.6, dt);
    benchmark::DoNotOptimize(torque);
    t += dt;
    if (t > p.duration_s()) t = 0;
  }
}
BENCHMARK(BM_ControllerUpdate);

} // namespace

BENCHMARK_MAIN();
