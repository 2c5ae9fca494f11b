// The twin's step (device tick + plant step + move tracking) against a bare
// mj_step of the same model, in one run (issue 5). One iteration = one
// IO-Link cycle = 20 physics steps of 0.1 ms. Prints the ratio and the
// real-time factor at the end. Figures: docs/performance-twin.md.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <ctime>
#include <map>
#include <string>

#include "device_logic/process_data.hpp"
#include "device_logic/units.hpp"
#include "twin/load_builder.hpp"
#include "twin/plant.hpp"
#include "twin/twin.hpp"

namespace sreh {
namespace {

constexpr double kLoad_gcm2 = 2000;
constexpr int kStepsPerCycle = 20;

void BM_BareMjStep(benchmark::State& state) {
  BuiltModel built = build_model(InertiaLoad{kLoad_gcm2}, {}, 1e-4);
  MjDataPtr data(mj_makeData(built.model.get()));
  int64_t k = 0;
  for (auto _ : state) {
    for (int i = 0; i < kStepsPerCycle; ++i, ++k) {
      data->ctrl[0] = (k / 2000) % 2 == 0 ? 0.3 : -0.3; // a torque square wave, 0.2 s period
      mj_step(built.model.get(), data.get());
    }
  }
  benchmark::DoNotOptimize(data->qpos[0]);
  state.counters["realtime_x"] = benchmark::Counter(2e-3 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_PlantStep(benchmark::State& state) {
  PlantConfig c;
  c.load = InertiaLoad{kLoad_gcm2};
  Plant plant(c);
  int64_t k = 0;
  for (auto _ : state) {
    for (int i = 0; i < kStepsPerCycle; ++i, ++k) {
      plant.step(MotorCommand{(k / 2000) % 2 == 0 ? 0.3 : -0.3, true});
    }
  }
  benchmark::DoNotOptimize(plant.angle_rad());
  state.counters["realtime_x"] = benchmark::Counter(2e-3 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// A PLC program: motor on, then moves between 0 and 90 deg, each started
// when the previous one is Done (manual 3.4 handshake: Move back to 0 first).
// The PLC of the benchmarks: 0 -> 90 -> 0 deg moves, one IO-Link cycle per call.
void plc_cycle(Twin& twin, ProcessDataOut& pd, bool& at_90) {
  const ProcessDataIn in = twin.pd_in();
  if (in.ready && !pd.move) {
    pd.target_raw = at_90 ? 0 : static_cast<int32_t>(deg_to_wire_counts(90));
    pd.move = true;
    at_90 = !at_90;
  } else if (in.done && pd.move) {
    pd.move = false;
  }
  twin.set_pd_out(pd);
  twin.run_cycle();
}

void BM_TwinCycle(benchmark::State& state) {
  TwinConfig c;
  c.load = InertiaLoad{kLoad_gcm2};
  c.record_trace = state.range(0) != 0;
  Twin twin(c);
  const uint8_t load_raw[2] = {static_cast<uint8_t>(2000 >> 8), static_cast<uint8_t>(2000 & 0xFF)};
  twin.isdu_write(65, 4, load_raw);
  ProcessDataOut pd;
  pd.motor_on = true;
  pd.parameter_set = 1;
  twin.set_pd_out(pd);
  bool at_90 = false;
  for (auto _ : state) {
    plc_cycle(twin, pd, at_90);
  }
  state.counters["moves"] = static_cast<double>(twin.moves().size());
  state.counters["realtime_x"] = benchmark::Counter(2e-3 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// The workload of python/bench_python.py's run_cycles (issue 19): one
// constant output frame (motor on, Move to 90 deg with set 1), trace off, so
// that the Python figure can be set against this one.
void BM_TwinRunCycles(benchmark::State& state) {
  TwinConfig c;
  c.load = InertiaLoad{kLoad_gcm2};
  c.record_trace = false;
  Twin twin(c);
  const uint8_t load_raw[2] = {static_cast<uint8_t>(2000 >> 8), static_cast<uint8_t>(2000 & 0xFF)};
  twin.isdu_write(65, 4, load_raw);
  ProcessDataOut pd;
  pd.motor_on = true;
  pd.parameter_set = 1;
  pd.move = true;
  pd.target_raw = static_cast<int32_t>(deg_to_wire_counts(90));
  twin.set_pd_out(pd);
  for (auto _ : state) {
    twin.run_cycle();
  }
  state.counters["realtime_x"] = benchmark::Counter(2e-3 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// Interleaved: 10 IO-Link cycles of bare mj_step, then 10 of the twin, each
// timed with the thread's CPU clock, so both see the same machine load (the
// shared 2-core machine is noisy). Counters: us per physics step, ratio.
double thread_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

void BM_PairedTwinVsBare(benchmark::State& state) {
  BuiltModel built = build_model(InertiaLoad{kLoad_gcm2}, {}, 1e-4);
  MjDataPtr data(mj_makeData(built.model.get()));
  TwinConfig c;
  c.load = InertiaLoad{kLoad_gcm2};
  Twin twin(c);
  const uint8_t load_raw[2] = {static_cast<uint8_t>(2000 >> 8), static_cast<uint8_t>(2000 & 0xFF)};
  twin.isdu_write(65, 4, load_raw);
  ProcessDataOut pd;
  pd.motor_on = true;
  pd.parameter_set = 1;
  bool at_90 = false;
  int64_t k = 0;
  double bare_s = 0, twin_s = 0;
  constexpr int kChunk = 10;
  for (auto _ : state) {
    const double t0 = thread_cpu_s();
    for (int n = 0; n < kChunk * kStepsPerCycle; ++n, ++k) {
      data->ctrl[0] = (k / 2000) % 2 == 0 ? 0.3 : -0.3;
      mj_step(built.model.get(), data.get());
    }
    const double t1 = thread_cpu_s();
    for (int n = 0; n < kChunk; ++n) {
      plc_cycle(twin, pd, at_90);
    }
    const double t2 = thread_cpu_s();
    bare_s += t1 - t0;
    twin_s += t2 - t1;
  }
  benchmark::DoNotOptimize(data->qpos[0]);
  const double steps = static_cast<double>(state.iterations()) * kChunk * kStepsPerCycle;
  state.counters["bare_us_per_step"] = 1e6 * bare_s / steps;
  state.counters["twin_us_per_step"] = 1e6 * twin_s / steps;
  state.counters["ratio"] = twin_s / bare_s;
  state.counters["twin_realtime_x"] = steps * 1e-4 / twin_s;
}

// The process-data codec alone (issue 30: driven by the field table): one
// IO-Link cycle's worth, out encoded and decoded, in encoded and decoded, as
// the twin and the device do every cycle. The frames change each iteration
// so nothing is folded away.
void BM_PdCodecCycle(benchmark::State& state) {
  ProcessDataOut out;
  out.motor_on = true;
  out.parameter_set = 3;
  ProcessDataIn in;
  in.ready = true;
  in.warning_code = 0x40;
  int32_t k = 0;
  for (auto _ : state) {
    out.target_raw = k;
    out.move = (k & 1) != 0;
    in.position_raw = -k;
    in.busy = (k & 2) != 0;
    ++k;
    const ProcessDataOut o = decode_out(encode(out));
    const ProcessDataIn i = decode_in(encode(in));
    benchmark::DoNotOptimize(o);
    benchmark::DoNotOptimize(i);
  }
}

BENCHMARK(BM_PairedTwinVsBare)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BareMjStep)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PlantStep)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TwinCycle)->Arg(0)->Arg(1)->ArgName("trace")->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TwinRunCycles)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PdCodecCycle)->Unit(benchmark::kNanosecond);

// Console output plus the ratio twin / bare at the end.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    // CPU time: on a shared 2-core machine wall time mostly measures the
    // neighbours. With --benchmark_repetitions the median is kept.
    for (const Run& r : runs) {
      if (r.run_type == Run::RT_Iteration && !us_per_cycle_.count(r.run_name.str())) {
        us_per_cycle_[r.run_name.str()] = r.GetAdjustedCPUTime();
      } else if (r.run_type == Run::RT_Aggregate && r.aggregate_name == "median") {
        us_per_cycle_[r.run_name.str()] = r.GetAdjustedCPUTime();
      }
    }
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    const auto bare = us_per_cycle_.find("BM_BareMjStep");
    if (bare == us_per_cycle_.end()) return;
    for (const auto& [name, us] : us_per_cycle_) {
      if (name.rfind("BM_Paired", 0) == 0) continue; // reports its own counters
      std::printf("%-24s %7.2f us/cycle (CPU)  %6.3f us/step  %7.1fx real time  %5.2fx bare mj_step\n", name.c_str(), us,
                  us / kStepsPerCycle, 2000.0 / us, us / bare->second);
    }
  }

 private:
  std::map<std::string, double> us_per_cycle_;
};

} // namespace
} // namespace sreh

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  sreh::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
