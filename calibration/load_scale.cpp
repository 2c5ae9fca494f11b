#include "calibration/load_scale.hpp"

#include <type_traits>

#include <fmt/format.h>

#include "calibration/master_log.hpp"
#include "twin/load_builder.hpp"

namespace sreh {
namespace {

// One part's shape with its mass times `f`; false for an MJCF body.
template <class Shape> bool scale_shape(Shape& s, double f) {
  if constexpr (std::is_same_v<Shape, MjcfLoad> || std::is_same_v<Shape, NoLoad>) {
    return std::is_same_v<Shape, NoLoad>;
  } else if constexpr (std::is_same_v<Shape, InertiaLoad>) {
    s.inertia_gcm2 *= f;
    return true;
  } else if constexpr (std::is_same_v<Shape, MeshPart>) {
    s.mass_kg *= f; // one of the two is 0
    s.density_kg_m3 *= f;
    return true;
  } else if constexpr (std::is_same_v<Shape, ArmLoad>) {
    s.mass_kg *= f;
    s.arm_mass_kg *= f;
    return true;
  } else if constexpr (std::is_same_v<Shape, AssemblyLoad>) {
    for (LoadPart& p : s.parts) {
      if (!std::visit([f](auto& shape) { return scale_shape(shape, f); }, p.shape)) return false;
    }
    return true;
  } else {
    s.mass_kg *= f;
    return true;
  }
}

} // namespace

bool is_load_name(const std::string& name) { return name == "load" || name == "load_inertia"; }

std::string why_not_scalable(const LoadSpec& load) {
  LoadSpec copy = load;
  if (std::visit([](auto& s) { return scale_shape(s, 1.0); }, copy)) return "";
  return fmt::format("{} includes an MJCF body file, whose inertials the fit cannot scale (state the load as "
                     "--load-gcm2 or a load file of shapes)",
                     describe_load(load));
}

LoadSpec scaled_load(const LoadSpec& load, double factor, const std::string& what) {
  LoadSpec copy = load;
  if (!std::visit([factor](auto& s) { return scale_shape(s, factor); }, copy)) {
    throw CalibrationInputError(fmt::format("{}: {}", what, why_not_scalable(load)));
  }
  return copy;
}

} // namespace sreh
