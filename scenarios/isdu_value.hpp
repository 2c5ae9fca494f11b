// ISDU values in scenarios: raw wire values encoded with the parameter
// table's type (manual chapter 6), and answers decoded the same way.
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "device_logic/parameter_table.hpp"
#include "scenarios/yaml_reader.hpp"

namespace sreh::detail {

// `value` of an isdu write: a number for numeric parameters (checked to fit
// the wire type, not the parameter's range: the device answers that), any
// scalar for string parameters, a list of numbers for a whole record
// (subindex 0). Unknown index/subindex: numbers take the smallest of 1, 2, 4
// octets that holds them, texts their bytes (the device answers 0x8011).
std::vector<uint8_t> encode_isdu_value(const YamlReader& reader, const YAML::Node& value, uint16_t index,
                                       uint8_t subindex, std::string_view what);

// The numeric value of an answer: decoded with the table's type where the
// parameter is known and numeric, else as an unsigned big-endian number.
// nullopt if the answer is not a number of 1..8 octets.
std::optional<int64_t> decode_isdu_number(uint16_t index, uint8_t subindex, std::span<const uint8_t> data);

// Text of a string answer (trailing NULs dropped, as IO-Link pads strings).
std::string decode_isdu_text(std::span<const uint8_t> data);

// The raw range a wire type can carry (not the parameter's own range);
// {0, 0} for texts. Shared with serve's JSON parameter writes.
std::pair<int64_t, int64_t> wire_range(ParamType type);

// Smallest big-endian form (1, 2 or 4 octets) of a number for an index the
// table does not know, so the device can answer 0x8011/0x8012.
std::vector<uint8_t> encode_untyped(int64_t value);

// Whether the table declares this variable as a string or octet string.
bool is_text_parameter(uint16_t index, uint8_t subindex);

} // namespace sreh::detail
