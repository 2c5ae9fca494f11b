// GET /v1/parameters (issue 39): the parameter table (manual chapter 6) as
// JSON, for the live page's parameter editor and any HMI: names, units,
// ranges and defaults, so that a client writes 900 deg/s, not 9000.
#pragma once
#include <nlohmann/json.hpp>

namespace sreh::serve {

// One object per numeric index/subindex: index, subindex, name, record,
// type, access (r, rw, w), persistent (survives a power cycle), unit,
// scale (display value = raw * scale), min, max, default (raw), notes,
// section. Strings and records whole are left out (not editable as numbers).
const nlohmann::ordered_json& parameter_catalog();

} // namespace sreh::serve
