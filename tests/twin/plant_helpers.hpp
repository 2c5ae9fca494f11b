// Helpers the plant tests share (plant_test.cpp, plant_load_test.cpp).
#pragma once
#include <utility>

#include "twin/plant.hpp"

namespace sreh::test {

// The default plant configuration carrying `load`.
inline PlantConfig config_with(LoadSpec load) {
  PlantConfig c;
  c.load = std::move(load);
  return c;
}

} // namespace sreh::test
