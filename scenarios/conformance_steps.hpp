// Parsers of the steps a conformance test needs beyond the basics (issue 15):
// set, save, link up/down, power with off time and turning, expect_bytes
// patterns. Internal to the scenario parser; keys in scenarios/README.md.
#pragma once
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "scenarios/scenario.hpp"
#include "scenarios/yaml_reader.hpp"

namespace sreh::detail {

// manual 1: minimum cycle 2 ms; IO-Link's MasterCycleTime ends at 132.8 ms (A-LINK-2).
inline constexpr double kMinCycleS = 0.002;
inline constexpr double kMaxCycleS = 0.1328;

bool integer_multiple(double a, double b);

// "01 A2 xx 3F": octets in hex, spaces free, xx not checked (nullopt).
std::vector<std::optional<uint8_t>> parse_hex_pattern(const YamlReader& r, const YAML::Node& n, const std::string& what);
SetStep parse_set(const YamlReader& r, const YAML::Node& n, const std::string& what, double physics_dt_s);
SaveStep parse_save(const YamlReader& r, const YAML::Node& n, const std::string& what, std::set<std::string>& saved);
LinkStep parse_link(const YamlReader& r, const YAML::Node& n, const std::string& what);
PowerCycleStep parse_power(const YamlReader& r, const YAML::Node& n, const std::string& what);
FirmwareStep parse_firmware(const YamlReader& r, const YAML::Node& n, const std::string& what);

} // namespace sreh::detail
