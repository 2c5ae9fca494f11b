// `load show --picture PNG` (issue 28): the load on the module, from above
// and from the side, with the flange axis (red) and the load's centre of
// mass (yellow) marked; off-screen (OSMesa), written atomically.
#pragma once
#include <string>

#include "twin/load_figures.hpp"
#include "twin/specs.hpp"

namespace sreh {

void write_load_picture(const LoadSpec& load, const LoadFigures& figures, const std::string& png_path);

} // namespace sreh
