// Frames rendered + encoded per second (issue 7): the straightforward loop
// (render, read, pipe to ffmpeg on one thread; 4x MSAA, shadows with a 4096
// map and reflections: MuJoCo's defaults) against the pipeline
// VideoRecorder uses by default (writer thread; 4x MSAA, no shadows, no
// reflections). `fps` is wall-clock throughput; `cpu_ms_per_frame` counts
// every thread of this process and the ffmpeg child, so it stays meaningful
// on a loaded machine. Frames carry the full overlay, the time-scale banner
// and the automatic framing (issue 16). Figures: docs/performance-renders.md.
#include <benchmark/benchmark.h>
#include <mujoco/mujoco.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "renders/video.hpp"

namespace {

struct Variant {
  const char* name;
  bool threaded;
  int msaa;
  bool shadows;
  int shadow_size;
  bool reflections;
};

constexpr Variant kVariants[] = {
    {"reference_loop:msaa4+shadow4096+reflect", false, 4, true, 4096, true},
    {"threaded:msaa4+shadow4096+reflect", true, 4, true, 4096, true},
    {"unthreaded:msaa4", false, 4, false, 2048, false},
    {"threaded:msaa4(default)", true, 4, false, 2048, false},
    {"threaded:msaa4+shadow2048", true, 4, true, 2048, false},
    {"threaded:msaa0", true, 0, false, 2048, false},
};

double cpu_s() {
  double total = 0;
  for (int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
    rusage u{};
    getrusage(who, &u);
    total += static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  }
  return total;
}

void BM_VideoFrames(benchmark::State& state) {
  const Variant& v = kVariants[state.range(2)];
  const std::string model_path = std::string(SREH_SOURCE_DIR) + "/models/sreh50.xml";
  char error[1000] = "";
  mjModel* m = mj_loadXML(model_path.c_str(), nullptr, error, sizeof error);
  if (!m) {
    state.SkipWithError(error);
    return;
  }
  mjData* d = mj_makeData(m);
  mj_forward(m, d);
  const std::filesystem::path out =
      std::filesystem::temp_directory_path() / ("sreh_render_bench_" + std::to_string(getpid()) + ".mp4");

  constexpr int kFrames = 90; // 3 s of video at 30 fps
  uint64_t frames = 0;
  double cpu_total_s = 0;
  for (auto _ : state) {
    state.PauseTiming(); // context creation (0.4 s) is paid once per video, not per frame
    sreh::VideoOptions o;
    o.path = out;
    o.width_px = static_cast<int>(state.range(0));
    o.height_px = static_cast<int>(state.range(1));
    o.threaded = v.threaded;
    o.msaa_samples = v.msaa;
    o.shadows = v.shadows;
    o.shadow_size = v.shadow_size;
    o.reflections = v.reflections;
    // Issue 16: the full overlay, the time-scale banner (a time map at 20x)
    // and the automatic framing that keeps clear of them.
    o.time_map = sreh::TimeMap::constant(20.0, kFrames / 30.0 / 20.0);
    sreh::VideoRecorder rec(m, o);
    const double cpu0 = cpu_s();
    state.ResumeTiming();
    for (int k = 0; k < kFrames; ++k) {
      d->qpos[0] = 0.05 * k; // the flange turns: every frame differs
      mj_kinematics(m, d);
      sreh::FrameInfo f;
      f.row.t_s = k / 30.0 / 20.0;
      f.step = "4 wait_until";
      f.row.pd_out = sreh::encode(sreh::ProcessDataOut{.target_raw = 49152, .parameter_set = 1}); // 270 deg (2^16 counts/rev)
      f.row.state = sreh::State::Busy;
      f.row.setpoint_deg = 3.0 * k;
      f.row.position_deg = 2.9 * k;
      f.row.led = sreh::LedColor::Green;
      rec.add_frame(m, d, f);
    }
    rec.finish(); // ffmpeg reaped: its CPU time is in RUSAGE_CHILDREN now
    cpu_total_s += cpu_s() - cpu0;
    frames += kFrames;
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(frames), benchmark::Counter::kIsRate);
  state.counters["cpu_ms_per_frame"] = 1e3 * cpu_total_s / static_cast<double>(frames);
  double load[1] = {0};
  if (getloadavg(load, 1) == 1) state.counters["loadavg"] = load[0];
  state.SetLabel(v.name);
  std::filesystem::remove(out);
  mj_deleteData(d);
  mj_deleteModel(m);
}

void Args(benchmark::internal::Benchmark* b) {
  for (auto [w, h] : {std::pair{640, 480}, std::pair{1280, 720}})
    for (int v = 0; v < static_cast<int>(std::size(kVariants)); ++v) b->Args({w, h, v});
}

BENCHMARK(BM_VideoFrames)->Apply(Args)->Iterations(1)->UseRealTime()->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
