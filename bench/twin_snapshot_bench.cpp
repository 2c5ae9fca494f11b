// Twin::snapshot() / restore() cost (issue 13, A-TWIN-34): a loaded twin
// mid-move. Restore with the same load copies; with another load it
// recompiles the MuJoCo model. Figures: docs/performance-twin.md.
#include <benchmark/benchmark.h>

#include <fstream>
#include <vector>

#include "device_logic/units.hpp"
#include "twin/plant.hpp"
#include "twin/twin.hpp"
#include "twin/twin_snapshot.hpp"

namespace sreh {
namespace {

Twin& mid_move_twin() {
  static Twin* twin = [] {
    TwinConfig c;
    c.load = InertiaLoad{2000};
    auto* t = new Twin(c);
    ProcessDataOut pd;
    pd.motor_on = true;
    pd.parameter_set = 1;
    t->set_pd_out(pd);
    for (int i = 0; i < 20; ++i) t->run_cycle();
    pd.move = true;
    pd.target_raw = static_cast<int32_t>(deg_to_wire_counts(90));
    t->set_pd_out(pd);
    for (int i = 0; i < 30; ++i) t->run_cycle();
    return t;
  }();
  return *twin;
}

void BM_TwinSnapshot(benchmark::State& state) {
  Twin& twin = mid_move_twin();
  for (auto _ : state) benchmark::DoNotOptimize(twin.snapshot());
  // Memory: the copied mjData (buffer + stack) dominates a snapshot.
  const TwinSnapshot s = twin.snapshot();
  state.counters["mjdata_kB"] = (s.plant.data->nbuffer + 8.0 * s.plant.data->nstack) / 1024.0;
  // What 100 kept snapshots add to the resident set (pages actually touched).
  auto rss_kB = [] {
    std::ifstream statm("/proc/self/statm");
    double size = 0, resident = 0;
    statm >> size >> resident;
    return resident * 4.0;
  };
  const double before = rss_kB();
  std::vector<TwinSnapshot> kept;
  for (int i = 0; i < 100; ++i) kept.push_back(twin.snapshot());
  state.counters["rss_kB_per_snapshot"] = (rss_kB() - before) / 100.0;
}

void BM_TwinRestore(benchmark::State& state) {
  Twin& twin = mid_move_twin();
  const TwinSnapshot snap = twin.snapshot();
  for (auto _ : state) twin.restore(snap);
}

// A snapshot taken before a load change (Twin::set_load): restore rebuilds the model.
void BM_TwinRestoreOtherLoad(benchmark::State& state) {
  Twin& twin = mid_move_twin();
  const TwinSnapshot light = twin.snapshot();
  twin.set_load(InertiaLoad{4000});
  const TwinSnapshot heavy = twin.snapshot();
  bool to_light = true;
  for (auto _ : state) {
    twin.restore(to_light ? light : heavy);
    to_light = !to_light;
  }
  twin.restore(light);
}

// One snapshot, then 100 cycles and back: a "try something" loop.
void BM_TwinTry100Cycles(benchmark::State& state) {
  Twin& twin = mid_move_twin();
  const TwinSnapshot snap = twin.snapshot();
  for (auto _ : state) {
    for (int i = 0; i < 100; ++i) twin.run_cycle();
    twin.restore(snap);
  }
}

BENCHMARK(BM_TwinSnapshot)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TwinRestore)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TwinRestoreOtherLoad)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TwinTry100Cycles)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace sreh

BENCHMARK_MAIN();
