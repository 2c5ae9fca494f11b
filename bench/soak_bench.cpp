// Soak (issue 12): 10^6 IO-Link cycles (2000 s simulated) of back-and-forth
// moves through the scenario runner with the trace on, streamed to a file as
// `sreh-twin run --trace` does. Reports the real-time factor and the
// resident memory after 1 %, 50 % and 100 % of the run: flat memory means
// nothing grows with run length. Figures: docs/performance-reliability.md.
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

#include <benchmark/benchmark.h>

#include "scenarios/runner.hpp"
#include "scenarios/scenario_parser.hpp"
#include "twin/trace.hpp"

namespace {

double rss_MB() {
  long pages = 0, resident = 0;
  std::ifstream statm("/proc/self/statm");
  statm >> pages >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

void BM_Soak1e6Cycles(benchmark::State& state) {
  const sreh::Scenario scenario = sreh::parse_scenario_file(SREH_SOURCE_DIR "/bench/data/soak_2000s.yaml");
  const std::string trace_path = "/tmp/sreh_soak_" + std::to_string(::getpid()) + ".csv";
  double rss_1pct = 0, rss_50pct = 0, rss_end = 0, sim_s = 0;
  uint64_t cycles = 0;
  for (auto _ : state) {
    std::ofstream out(trace_path, std::ios::binary);
    sreh::write_trace_header(out);
    uint64_t n = 0;
    sreh::RunOptions options;
    options.trace_sink = [&](const sreh::TraceRow& row) {
      sreh::write_trace_row(out, row);
      ++n;
      if (n == 10000) rss_1pct = rss_MB();
      if (n == 500000) rss_50pct = rss_MB();
    };
    const sreh::RunResult r = sreh::run_scenario(scenario, options);
    rss_end = rss_MB();
    cycles = r.cycles;
    sim_s = r.sim_time_s;
    benchmark::DoNotOptimize(r.passed);
  }
  std::remove(trace_path.c_str());
  state.counters["cycles"] = static_cast<double>(cycles);
  state.counters["sim_s"] = sim_s;
  state.counters["rss_MB_at_1pct"] = rss_1pct;
  state.counters["rss_MB_at_50pct"] = rss_50pct;
  state.counters["rss_MB_at_end"] = rss_end;
  // Simulated seconds per wall second (> 1: faster than real time).
  state.counters["real_time_factor"] = benchmark::Counter(sim_s * static_cast<double>(state.iterations()),
                                                          benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Soak1e6Cycles)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
