#include "scenarios/conformance_steps.hpp"

#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "scenarios/comparison_parser.hpp"
#include "scenarios/snapshot.hpp"
#include "scenarios/world.hpp"

namespace sreh::detail {
namespace {
constexpr double kMaxDurationS = 3600.0; // A-SCN-1, as for every duration
constexpr double kMaxTurnDeg = 36000.0;  // A-SCN-1: 100 revolutions by hand is plenty
constexpr double kMaxFirmwareKB = 4096.0; // the device's image limit (A-FW-4)
} // namespace

bool integer_multiple(double a, double b) {
  const double ratio = a / b;
  return std::abs(ratio - std::round(ratio)) <= 1e-6;
}

// "01 A2 xx 3F": octets in hex, spaces free, xx not checked.
std::vector<std::optional<uint8_t>> parse_hex_pattern(const YamlReader& r, const YAML::Node& n, const std::string& what) {
  std::string hex;
  for (char c : r.text(n, what)) {
    if (c != ' ' && c != '_') hex.push_back(c);
  }
  if (hex.empty() || hex.size() % 2 != 0) {
    r.fail(n, fmt::format("{}: expected pairs of hex digits (xx: not checked), got '{}'", what, n.Scalar()));
  }
  std::vector<std::optional<uint8_t>> out;
  for (std::size_t i = 0; i < hex.size(); i += 2) {
    const std::string pair = hex.substr(i, 2);
    if (pair == "xx" || pair == "XX") {
      out.emplace_back(std::nullopt);
      continue;
    }
    if (!std::isxdigit(static_cast<unsigned char>(pair[0])) || !std::isxdigit(static_cast<unsigned char>(pair[1]))) {
      r.fail(n, fmt::format("{}: octet {} '{}' is neither hex nor xx", what, i / 2 + 1, pair));
    }
    out.emplace_back(static_cast<uint8_t>(std::stoi(pair, nullptr, 16)));
  }
  return out;
}

SetStep parse_set(const YamlReader& r, const YAML::Node& n, const std::string& what, double physics_dt_s) {
  r.check_map(n, what, {"ambient_C", "master_cycle_s"});
  SetStep s;
  constexpr WorldRanges world{}; // the world block's ambient range (A-SCN-32)
  if (n["ambient_C"]) s.ambient_C = r.number(n["ambient_C"], what + ".ambient_C", world.min_ambient_C, world.max_ambient_C);
  if (const YAML::Node c = n["master_cycle_s"]) {
    s.master_cycle_s = r.number(c, what + ".master_cycle_s", kMinCycleS, kMaxCycleS);
    if (!integer_multiple(*s.master_cycle_s, physics_dt_s)) {
      r.fail(c, fmt::format("{}.master_cycle_s: {} must be an integer multiple of sim.physics_dt_s {}", what,
                             *s.master_cycle_s, physics_dt_s));
    }
  }
  if (!s.ambient_C && !s.master_cycle_s) r.fail(n, what + ": nothing to set (ambient_C, master_cycle_s)");
  return s;
}

SaveStep parse_save(const YamlReader& r, const YAML::Node& n, const std::string& what, std::set<std::string>& saved) {
  std::vector<std::string_view> keys(std::begin(kSavableQuantities), std::end(kSavableQuantities));
  r.check_map(n, what, keys);
  SaveStep s;
  for (const auto& kv : n) {
    const std::string key = kv.first.Scalar();
    const std::string name = read_variable_name(r, kv.second, what + "." + key);
    s.quantity_to_name.emplace_back(key, name);
  }
  if (s.quantity_to_name.empty()) r.fail(n, what + ": nothing to save (e.g. {position_deg: before})");
  for (const auto& [key, name] : s.quantity_to_name) saved.insert(name);
  return s;
}

LinkStep parse_link(const YamlReader& r, const YAML::Node& n, const std::string& what) {
  if (n.IsScalar() && !r.is_quoted(n)) {
    if (n.Scalar() == "down") return LinkStep{LinkStep::Mode::Down, 0};
    if (n.Scalar() == "up") return LinkStep{LinkStep::Mode::Up, 0};
    r.fail(n, fmt::format("{}: 'down', 'up' or {{down_s: S}}, got '{}'", what, n.Scalar()));
  }
  r.check_map(n, what, {"down_s"});
  return LinkStep{LinkStep::Mode::DownFor, r.number(r.require(n, "down_s", what), what + ".down_s", 0.0, kMaxDurationS)};
}

PowerCycleStep parse_power(const YamlReader& r, const YAML::Node& n, const std::string& what) {
  if (n.IsScalar()) {
    if (r.text(n, what) != "cycle") r.fail(n, fmt::format("{}: 'cycle' or {{off_s: S, turn_deg: A}}, got '{}'", what, n.Scalar()));
    return PowerCycleStep{};
  }
  r.check_map(n, what, {"off_s", "turn_deg"});
  PowerCycleStep p;
  p.off_s = r.number(r.require(n, "off_s", what), what + ".off_s", 0.0, kMaxDurationS);
  if (n["turn_deg"]) p.turn_deg = r.number(n["turn_deg"], what + ".turn_deg", -kMaxTurnDeg, kMaxTurnDeg);
  return p;
}

// firmware: {image: good|corrupt, version, size_kB, power_off_at, expect_error} (manual 9).
FirmwareStep parse_firmware(const YamlReader& r, const YAML::Node& v, const std::string& what) {
  r.check_map(v, what, {"image", "version", "size_kB", "power_off_at", "expect_error"});
  FirmwareStep f;
  const std::string image = r.text(r.require(v, "image", what), what + ".image");
  if (image != "good" && image != "corrupt") {
    r.fail(v["image"], fmt::format("{}.image: 'good' or 'corrupt', got '{}'", what, image));
  }
  f.corrupt = image == "corrupt";
  if (v["version"]) f.version = r.text(v["version"], what + ".version");
  if (v["size_kB"]) {
    f.size_B = static_cast<std::size_t>(std::llround(r.number(v["size_kB"], what + ".size_kB", 0.0, kMaxFirmwareKB) * 1024.0));
  }
  if (v["power_off_at"]) {
    if (v["expect_error"]) r.fail(v["expect_error"], what + ": give power_off_at or expect_error, not both (an interrupted transfer has no answer)");
    f.power_off_at = r.number(v["power_off_at"], what + ".power_off_at", 0.0, 1.0);
  }
  if (v["expect_error"]) f.expect_error = static_cast<uint16_t>(r.integer(v["expect_error"], what + ".expect_error", 0x8000, 0x80FF));
  return f;
}

} // namespace sreh::detail
