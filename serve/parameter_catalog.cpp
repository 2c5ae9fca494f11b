#include "serve/parameter_catalog.hpp"

#include "device_logic/parameter_table.hpp"

namespace sreh::serve {

const nlohmann::ordered_json& parameter_catalog() {
  static const nlohmann::ordered_json catalog = [] {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const ParameterEntry& row : parameter_table()) {
      if (!is_numeric(row.type)) continue;
      list.push_back({{"index", row.index},
                      {"subindex", row.subindex},
                      {"name", std::string(row.name)},
                      {"record", std::string(row.record_name)},
                      {"type", std::string(type_name(row.type))},
                      {"access", std::string(access_name(row.access))},
                      {"persistent", row.storage == Storage::Config || row.storage == Storage::PersistentDiag},
                      {"unit", std::string(row.display_unit)},
                      {"scale", row.display_scale},
                      {"min", row.min},
                      {"max", row.max},
                      {"default", row.default_value},
                      {"notes", std::string(row.notes)},
                      {"section", std::string(row.section)}});
    }
    return list;
  }();
  return catalog;
}

} // namespace sreh::serve
