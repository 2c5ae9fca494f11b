#include "scenarios/model_card_json.hpp"

namespace sreh {

nlohmann::ordered_json model_card_json(const ModelCard& card) {
  nlohmann::ordered_json constants = nlohmann::ordered_json::object();
  for (const ModelConstant& c : card.constants) {
    constants[c.name] = {{"value", c.value},
                         {"unit", c.unit},
                         {"source", c.source},
                         {"range", {c.range_lo, c.range_hi}}};
  }
  return {{"constants", constants}};
}

} // namespace sreh
