#include "renders/load_picture.hpp"

#include <algorithm>
#include <vector>

#include <fmt/format.h>

#include "io/atomic_file.hpp"
#include "renders/offscreen.hpp"
#include "renders/png_writer.hpp"
#include "twin/load_builder.hpp"
#include "twin/mujoco_support.hpp"

namespace sreh {
namespace {

constexpr int kViewWidth_px = 640; // each of the two views
constexpr int kViewHeight_px = 480;

// The axis as a thin red rod through the flange and the centre of mass as a
// yellow ball: world geoms that touch nothing.
std::string markers_xml(const LoadFigures& f) {
  const double x = f.face_world_m[0] + f.com_m[0], y = f.face_world_m[1] + f.com_m[1], z = f.face_world_m[2] + f.com_m[2];
  return fmt::format(
      "<geom name=\"picture_axis\" type=\"cylinder\" fromto=\"0 0 0.0 0 0 {}\" size=\"0.0012\" rgba=\"0.9 0.1 0.1 1\" "
      "contype=\"0\" conaffinity=\"0\"/>"
      "<geom name=\"picture_com\" type=\"sphere\" pos=\"{} {} {}\" size=\"0.004\" rgba=\"1 0.85 0 1\" contype=\"0\" "
      "conaffinity=\"0\"/>",
      f.face_world_m[2] + std::max(0.1, 2 * f.com_m[2] + 0.05), x, y, z);
}

} // namespace

void write_load_picture(const LoadSpec& load, const LoadFigures& figures, const std::string& png_path) {
  ComposedModel composed = compose_model(load, {});
  const std::size_t end = composed.xml.rfind("</worldbody>");
  composed.xml.insert(end, markers_xml(figures));
  const MjModelPtr model = compile_mjcf(composed.xml, "load picture", composed.files);
  MjDataPtr data(mj_makeData(model.get()));
  mj_forward(model.get(), data.get());
  RenderOptions options;
  options.width_px = kViewWidth_px;
  options.height_px = kViewHeight_px;
  OffscreenRenderer renderer(model.get(), options, CameraSpec::top());
  const RgbImage top = renderer.render(model.get(), data.get(), SceneState{});
  CameraSpec side;
  side.azimuth_deg = 90.0; // looking along +y: x to the right, z up
  side.elevation_deg = -5.0;
  renderer.set_camera(side);
  const RgbImage front = renderer.render(model.get(), data.get(), SceneState{});
  // Side by side: above | side.
  const int w = 2 * kViewWidth_px;
  std::vector<uint8_t> rgb(static_cast<std::size_t>(w) * kViewHeight_px * 3);
  for (int row = 0; row < kViewHeight_px; ++row) {
    const std::size_t line = static_cast<std::size_t>(kViewWidth_px) * 3;
    std::copy_n(top.rgb.begin() + static_cast<std::ptrdiff_t>(row * line), line, rgb.begin() + static_cast<std::ptrdiff_t>(row * 2 * line));
    std::copy_n(front.rgb.begin() + static_cast<std::ptrdiff_t>(row * line), line,
                rgb.begin() + static_cast<std::ptrdiff_t>(row * 2 * line + line));
  }
  io::AtomicFile file(png_path); // whole or not at all
  write_png(file.temp_path(), rgb.data(), w, kViewHeight_px);
  file.commit();
}

} // namespace sreh
