// A studio cycle as a cycle file (docs/sizing.md "Cycles", docs/studio.md
// "Cycles"): what `sreh-twin size --cycle PROJECT.yaml` reads.
#include <fmt/format.h>

#include "studio/project.hpp"

namespace sreh::studio {
namespace {

std::string num(double v) { return fmt::format("{}", v); }

// The load of the cycle's start and of a release: the parts that are not payload.
Json base_parts(const Json& s) {
  Json out = Json::array();
  for (const Json& p : s["parts"]) {
    if (!p["payload"].get<bool>()) out.push_back(p);
  }
  return out;
}

std::string load_node(const Json& parts, const std::string& indent) {
  if (parts.empty()) return " {inertia_gcm2: 0}\n";
  std::string o(1, '\n');
  o += parts_yaml(parts, indent);
  return o;
}

} // namespace

std::string cycle_file_yaml(const Json& state) {
  const Json s = normalised_state(state);
  std::string o = "name: " + Json(s["name"].get<std::string>()).dump() + "\n";
  o += "load:";
  o += load_node(base_parts(s), "  ");
  o += fmt::format("mounting: {{tilt_deg: {}}}\n", num(s["mounting_tilt_deg"].get<double>()));
  o += fmt::format("supply: {{voltage_V: {}}}\n", num(s["voltage_V"].get<double>()));
  o += fmt::format("ambient_C: {}\n", num(s["ambient_C"].get<double>()));
  o += fmt::format("tolerance_deg: {}\n", num(s["tolerance_deg"].get<double>()));
  o += "segments:\n";
  for (const Json& g : s["segments"]) {
    const std::string kind = g["kind"].get<std::string>();
    if (kind == "move") {
      o += fmt::format("  - {{move_deg: {}{}}}\n", num(g["deg"].get<double>()), g["relative"].get<bool>() ? ", relative: true" : "");
    } else if (kind == "dwell") {
      o += fmt::format("  - {{dwell_s: {}}}\n", num(g["s"].get<double>()));
    } else {
      o += "  - load:";
      o += load_node(kind == "grip" ? s["parts"] : base_parts(s), "      ");
    }
  }
  return o;
}

} // namespace sreh::studio
