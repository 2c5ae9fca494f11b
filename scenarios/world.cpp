#include "scenarios/world.hpp"

namespace sreh {

TwinConfig twin_config(const WorldSpec& world) {
  TwinConfig c;
  static_cast<WorldSpec&>(c) = world; // TwinConfig derives from WorldSpec (twin/twin.hpp): no field copied by hand
  return c;
}

} // namespace sreh
