// The attached load as a fitted quantity of the setup (issue 36, A-CAL-14):
// not a module constant, so never in the model file. The fit scales the
// stated load's inertia about the axis by one factor: every part's mass
// (or density, or a given inertia) times the factor, its shape and place
// kept, so its inertia about the axis scales by exactly that factor, in
// either direction, for any load file but a raw MJCF body (whose inertials
// the twin does not rewrite).
#pragma once
#include <string>
#include <vector>

#include "twin/specs.hpp"

namespace sreh {

// --fit names of the load: "load" and "load_inertia".
bool is_load_name(const std::string& name);

// The factor's range: the carried load within -30 % .. +30 % of the stated
// one, and never above the module's maximum (manual 6.2, 15000 g cm^2),
// which the twin refuses to carry.
inline constexpr double kLoadScaleLo = 0.7;
inline constexpr double kLoadScaleHi = 1.3;

// `load` with every mass (density, given inertia) times `factor`. Throws
// CalibrationInputError naming `what` for a load that cannot be scaled (an
// MJCF body file).
LoadSpec scaled_load(const LoadSpec& load, double factor, const std::string& what = "--fit load");

// Whether `load` can be scaled ("" if so, else why not, in words).
std::string why_not_scalable(const LoadSpec& load);

} // namespace sreh
