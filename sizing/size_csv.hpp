// `sreh-twin size --csv FILE` and the studio's CSV export (issue 37): the
// figures of the `size --json` object as two columns, one figure a row.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace sreh::sizing {

// "figure,value" then one row per number, text or flag of `size_json`,
// named by its path ("recommended.speed_dps", "moves.1.positioning_s");
// nulls as empty values, the ISDU writes as "index/subindex" rows.
// Deterministic: the JSON's key order.
std::string size_csv(const nlohmann::json& size_json);

} // namespace sreh::sizing
