#include "serve/ds_backup_file.hpp"

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "serve/port_api.hpp"

namespace sreh::serve {

std::string ds_backup_json(const DsBackup& b, bool download_owed) {
  nlohmann::json values = nlohmann::json::array();
  for (const auto& v : b.values)
    values.push_back({{"index", v.entry.index}, {"subindex", v.entry.subindex}, {"raw", hex_bytes(v.data)}});
  return nlohmann::json{{"checksum", b.checksum}, {"download_owed", download_owed}, {"values", values}}.dump(1) + "\n";
}

DsBackup ds_backup_from_json(const std::string& text, bool* download_owed) {
  DsBackup b;
  try {
    const auto j = nlohmann::json::parse(text);
    b.checksum = j.at("checksum").get<uint32_t>();
    if (download_owed != nullptr) *download_owed = j.value("download_owed", false);
    for (const auto& v : j.at("values")) {
      DsBackup::Value value;
      value.entry.index = v.at("index").get<uint16_t>();
      value.entry.subindex = v.at("subindex").get<uint8_t>();
      value.data = parse_hex(v.at("raw").get<std::string>(), "raw");
      b.values.push_back(std::move(value));
    }
  } catch (const std::exception&) {
    throw std::invalid_argument(
        "not a data storage backup ({\"checksum\", \"download_owed\", \"values\": [{index, subindex, raw}]})");
  }
  return b;
}

} // namespace sreh::serve
