// Twins for sizing runs. Building one compiles MJCF (mj_loadXML), which is
// serialised here so that sweep threads may build twins concurrently; the
// runs themselves are independent (each thread its own Twin).
#pragma once
#include <memory>

#include "twin/twin.hpp"

namespace sreh::sizing {

// Throws SizingInputError for a load the twin refuses (e.g. above
// 15000 g cm^2, manual 6.2 index 64.4).
std::unique_ptr<Twin> make_twin(const TwinConfig& config);

} // namespace sreh::sizing
