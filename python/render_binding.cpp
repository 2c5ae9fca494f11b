// Pictures and videos from Python (issue 39): Twin.render() -> an RGB array
// (what PositioningEnv.render() returns), and run_scenario(...,
// video=, report=) writing what `sreh-twin run --video/--report` writes,
// through the same renders/ code. Without rendering (SREH_WITH_RENDER off)
// both raise RuntimeError.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cstring>
#include <optional>
#include <regex>

#include "io/output_path.hpp"
#include "python/bindings.hpp"
#include "scenarios/result_json.hpp"
#include "scenarios/runner.hpp"
#include "scenarios/scenario_parser.hpp"
#include "twin/load_builder.hpp"
#include "twin/plant.hpp"
#include "twin/twin.hpp"
#ifdef SREH_WITH_RENDER
#include "renders/ffmpeg_encoder.hpp"
#include "renders/offscreen.hpp"
#include "renders/run_media.hpp"
#include "renders/video.hpp"
#endif

namespace sreh::py {

#ifdef SREH_WITH_RENDER
struct TwinRenderer {
  std::unique_ptr<OffscreenRenderer> renderer;
  int width = 0, height = 0;
  bool overlay = false;
};
#else
struct TwinRenderer {};
#endif
void TwinRendererDeleter::operator()(TwinRenderer* r) const { delete r; }

pyb::object render_twin(const Twin& twin, std::unique_ptr<TwinRenderer, TwinRendererDeleter>& cache, int width, int height,
                        bool overlay) {
#ifdef SREH_WITH_RENDER
  if (width < 16 || height < 16 || width > 4096 || height > 4096 || width % 2 || height % 2) {
    throw input_error("render: width and height must be even, 16 .. 4096 pixels");
  }
  const Plant& plant = twin.plant();
  if (!cache || cache->width != width || cache->height != height || cache->overlay != overlay) {
    RenderOptions o;
    o.width_px = width;
    o.height_px = height;
    o.leave_overlay_room = overlay;
    cache.reset(new TwinRenderer);
    try {
      cache->renderer = std::make_unique<OffscreenRenderer>(plant.model(), o);
    } catch (const std::runtime_error& e) {
      cache.reset();
      throw std::runtime_error(std::string("render: ") + e.what());
    }
    cache->width = width;
    cache->height = height;
    cache->overlay = overlay;
  }
  // What a video frame of the same cycle shows (renders/video.cpp).
  FrameInfo info;
  info.row = twin.last_row();
  info.ghost_joint_rad = plant.ghost_angle_rad();
  SceneState scene;
  scene.led = info.row.led;
  scene.ghost_joint_rad = info.ghost_joint_rad;
  if (overlay) scene.overlay = overlay_lines(info);
  pyb::array_t<uint8_t> image({height, width, 3});
  cache->renderer->render_into(plant.model(), plant.data(), scene, image.mutable_data(), true);
  return image;
#else
  (void)twin, (void)cache, (void)width, (void)height, (void)overlay;
  throw std::runtime_error("render: this sreh_twin was built without rendering (SREH_WITH_RENDER=OFF)");
#endif
}

namespace {

struct MediaArgs {
  std::optional<std::string> video, frames, report;
  std::string size = "1280x720";
  int fps = 30;
  std::optional<double> slowmo;
};

#ifdef SREH_WITH_RENDER
RunMediaOptions media_options(const MediaArgs& a) {
  RunMediaOptions m;
  if (a.video || a.frames) {
    VideoOptions v;
    if (a.video && !container_for(*a.video)) throw input_error("video " + *a.video + ": the extension must be .mp4, .webm or .gif");
    if (a.video) v.path = *a.video;
    if (a.frames) v.frames_dir = *a.frames;
    std::smatch wh;
    if (!std::regex_match(a.size, wh, std::regex("([1-9][0-9]{1,3})x([1-9][0-9]{1,3})"))) {
      throw input_error("size '" + a.size + "': expected WIDTHxHEIGHT, e.g. 1280x720");
    }
    v.width_px = std::stoi(wh[1].str());
    v.height_px = std::stoi(wh[2].str());
    if (a.fps < 1 || a.fps > 240) throw input_error("fps " + std::to_string(a.fps) + ": expected 1 .. 240");
    v.fps = a.fps;
    if (a.slowmo && !(*a.slowmo >= 0.01 && *a.slowmo <= 1000)) throw input_error("slowmo: expected 0.01 .. 1000");
    v.slowmo = a.slowmo.value_or(1.0);
    m.video = v;
  }
  m.fixed_slowmo = a.slowmo.has_value();
  m.report_dir = a.report.value_or("");
  m.command_line = "sreh_twin.run_scenario(...)";
  m.version = SREH_VERSION;
  return m;
}
#endif

pyb::object run(const std::string& source, bool is_text, const std::string& base_dir, const MediaArgs& a) {
  Scenario scenario;
  try {
    scenario = is_text ? parse_scenario_text(source, "<scenario text>", base_dir) : parse_scenario_file(source);
  } catch (const ScenarioError& e) {
    throw input_error(e.what());
  }
  const bool media = a.video || a.frames || a.report;
#ifndef SREH_WITH_RENDER
  if (media) throw std::runtime_error("video / report: this sreh_twin was built without rendering (SREH_WITH_RENDER=OFF)");
#else
  std::vector<std::string> inputs;
  if (!is_text) inputs.push_back(source);
  for (const std::string& f : load_input_files(scenario.world.load)) inputs.push_back(f);
  try { // the CLI's output rule, before the run (issue 12)
    io::check_outputs({{"video", a.video.value_or(""), io::OutputKind::File},
                       {"frames", a.frames.value_or(""), io::OutputKind::EmptyFolder},
                       {"report", a.report.value_or(""), io::OutputKind::Folder}},
                      inputs);
  } catch (const io::PathError& e) {
    throw input_error(e.what());
  }
  std::optional<RunMedia> recorder;
  if (media) recorder.emplace(scenario, media_options(a));
#endif
  RunResult result;
  double wall_s = 0;
  try {
    pyb::gil_scoped_release release;
    RunOptions options;
#ifdef SREH_WITH_RENDER
    if (recorder) recorder->attach(options);
#endif
    const auto start = std::chrono::steady_clock::now();
    result = run_scenario(scenario, options);
    wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
#ifdef SREH_WITH_RENDER
    if (recorder) {
      recorder->render_video(result);
      recorder->write_report(result);
    }
#endif
  } catch (const ScenarioError& e) {
    throw input_error(e.what());
  } catch (const std::invalid_argument& e) {
    throw input_error(e.what());
  }
  nlohmann::json j = to_json(result); // as `run --json`, with its measured wall time (issue 25)
  j["wall_s"] = wall_s;
  j["real_time_factor"] = wall_s > 0 ? result.sim_time_s / wall_s : 0.0;
  return to_python(j);
}

} // namespace

void bind_render(pyb::module_& m) {
  using pyb::arg;
  m.def(
      "run_scenario",
      [](const std::string& source, bool is_text, const std::string& base_dir, std::optional<std::string> video,
         std::optional<std::string> frames, std::optional<std::string> report, const std::string& size, int fps,
         std::optional<double> slowmo) {
        return run(source, is_text, base_dir, MediaArgs{video, frames, report, size, fps, slowmo});
      },
      arg("source"), pyb::kw_only(), arg("is_text") = false, arg("base_dir") = "", arg("video") = pyb::none(),
      arg("frames") = pyb::none(), arg("report") = pyb::none(), arg("size") = "1280x720", arg("fps") = 30,
      arg("slowmo") = pyb::none(),
      "Run a scenario (a file, or YAML text with is_text) as `sreh-twin run --json`; video / frames / report write "
      "what `run --video / --frames / --report` write. Raises InputError for a bad scenario or option.");
#ifdef SREH_WITH_RENDER
  m.attr("RENDERING") = true;
#else
  m.attr("RENDERING") = false;
#endif
}

} // namespace sreh::py
