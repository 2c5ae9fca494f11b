#include "sizing/size_csv.hpp"

#include <fmt/format.h>

namespace sreh::sizing {
namespace {

// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

void rows(std::string& out, const nlohmann::json& j, const std::string& path) {
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) rows(out, it.value(), path.empty() ? it.key() : path + "." + it.key());
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) {
      const nlohmann::json& e = j[i];
      if (e.is_object() && e.contains("index") && e.contains("subindex") && e.contains("value")) { // an ISDU write
        out += field(fmt::format("{}.{}/{}", path, e["index"].get<int>(), e["subindex"].get<int>())) + "," +
               field(e["value"].dump()) + "\n";
      } else {
        rows(out, e, fmt::format("{}.{}", path, i + 1));
      }
    }
  } else {
    const std::string value = j.is_null() ? "" : j.is_string() ? j.get<std::string>() : j.dump();
    out += field(path) + "," + field(value) + "\n";
  }
}

} // namespace

std::string size_csv(const nlohmann::json& size_json) {
  std::string out = "figure,value\n";
  rows(out, size_json, "");
  return out;
}

} // namespace sreh::sizing
