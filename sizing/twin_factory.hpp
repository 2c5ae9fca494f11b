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

// A twin exactly as make_twin(config) builds it, for one run on this
// thread (issue 31): each thread keeps the last few twins it built with a
// snapshot taken right after construction, and hands out one of the same
// world restored to that snapshot (Twin::restore continues bit for bit,
// A-TWIN-34): ~50 us instead of ~1 ms for a construction. The reference is
// valid until this thread's next call. Configs with a trace or move sink or
// a memory image are not kept (sizing uses none): std::logic_error.
Twin& fresh_twin(const TwinConfig& config);

} // namespace sreh::sizing
