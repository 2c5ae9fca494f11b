// Frames rendered + encoded per second (issue 7): the straightforward loop
// (render, read, pipe to ffmpeg on one thread, 4x MSAA, 4096 shadow map:
// MuJoCo's defaults) against the pipeline VideoRecorder uses by default
// (writer thread, 1024 shadow map). Figures: docs/performance-renders.md.
#include <benchmark/benchmark.h>
#include <mujoco/mujoco.h>
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
};

constexpr Variant kVariants[] = {
    {"reference_loop_msaa4_shadow4096", false, 4, true, 4096},
    {"threaded_msaa4_shadow4096", true, 4, true, 4096},
    {"threaded_msaa4_shadow1024_default", true, 4, true, 1024},
    {"threaded_msaa2_shadow1024", true, 2, true, 1024},
    {"threaded_msaa0_noshadow", true, 0, false, 1024},
};

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
    sreh::VideoRecorder rec(m, o);
    state.ResumeTiming();
    for (int k = 0; k < kFrames; ++k) {
      d->qpos[0] = 0.05 * k; // the flange turns: every frame differs
      mj_kinematics(m, d);
      sreh::FrameInfo f;
      f.t_s = k / 30.0;
      f.setpoint_deg = 3.0 * k;
      f.position_deg = 2.9 * k;
      f.led = sreh::LedColor::Green;
      rec.add_frame(m, d, f);
    }
    rec.finish();
    frames += kFrames;
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(frames), benchmark::Counter::kIsRate);
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
