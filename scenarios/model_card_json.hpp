// The model card as JSON (issue 25, interfaces.md): `model show --json`
// and Python's model_card():
//   {"constants": {NAME: {"value", "unit", "source", "range": [lo, hi]}}}
// in the card's order.
#pragma once
#include <nlohmann/json.hpp>

#include "twin/model_card.hpp"

namespace sreh {

nlohmann::ordered_json model_card_json(const ModelCard& card);

} // namespace sreh
