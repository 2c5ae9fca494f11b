// Sizing throughput (issue 31): one recommended `size`, one evaluated set,
// the parts a run is made of (a twin from the pool, a cold and a cached
// model build), and the 200-point grid of docs/performance-sizing.md on two
// threads. Figures: docs/performance-sizing.md; the CLI figures before and
// after come from bench/sizing_throughput.sh.
#include <benchmark/benchmark.h>

#include <string>

#include "sizing/sizing.hpp"
#include "sizing/sweep.hpp"
#include "sizing/twin_factory.hpp"
#include "twin/load_builder.hpp"
#include "twin/model_cache.hpp"

namespace sreh::sizing {
namespace {

SizingRequest request(double angle_deg, double load_gcm2) {
  SizingRequest rq;
  rq.angle_deg = angle_deg;
  rq.world.load = InertiaLoad{load_gcm2};
  return rq;
}

// `size --angle-deg 360 --load-gcm2 15000`: a heat-limited search.
void BM_SizeSearch360(benchmark::State& state) {
  const SizingRequest rq = request(360, 15000);
  for (auto _ : state) benchmark::DoNotOptimize(size(rq));
}

// One evaluated set (2 back-and-forth cycles of 90 deg, 5000 g cm^2).
void BM_Evaluate90(benchmark::State& state) {
  const SizingRequest rq = request(90, 5000);
  const ParameterSetValues set = make_parameter_set(rq, MotionSetting{2000, 100, 100}, 5000);
  for (auto _ : state) benchmark::DoNotOptimize(evaluate(rq, set, false));
}

// A sizing twin restored from the pool (the same world again).
void BM_FreshTwinFromPool(benchmark::State& state) {
  TwinConfig cfg;
  cfg.load = InertiaLoad{5000};
  cfg.visual_detail = false;
  for (auto _ : state) benchmark::DoNotOptimize(&*fresh_twin(cfg));
}

// A lean model from the cache vs. compiled (the cache emptied each time).
void BM_BuildModelCached(benchmark::State& state) {
  const MechanicsConstants& m = default_module_model().mechanics;
  for (auto _ : state) {
    benchmark::DoNotOptimize(build_model(InertiaLoad{5000}, {}, 1e-4, m, default_module_model_path(), false));
  }
}

void BM_BuildModelCold(benchmark::State& state) {
  const MechanicsConstants& m = default_module_model().mechanics;
  for (auto _ : state) {
    clear_model_cache();
    benchmark::DoNotOptimize(build_model(InertiaLoad{5000}, {}, 1e-4, m, default_module_model_path(), false));
  }
}

// The 200-point grid: loads 0 .. 14250 step 750 x 10 angles, fastest set per point.
void BM_Grid200(benchmark::State& state) {
  SweepRequest rq;
  for (int i = 0; i <= 19; ++i) rq.loads_gcm2.push_back(750.0 * i);
  rq.angles_deg = {10, 30, 45, 60, 90, 120, 180, 270, 360, 720};
  rq.voltages_V = {24};
  rq.threads = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(run_sweep(rq));
}

BENCHMARK(BM_SizeSearch360)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Evaluate90)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FreshTwinFromPool)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BuildModelCached)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BuildModelCold)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Grid200)->Arg(1)->Arg(2)->Iterations(1)->UseRealTime()->MeasureProcessCPUTime()->Unit(benchmark::kSecond);

} // namespace
} // namespace sreh::sizing

BENCHMARK_MAIN();
