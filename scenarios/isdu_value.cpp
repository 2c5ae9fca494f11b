#include "scenarios/isdu_value.hpp"
#include "device_logic/byte_order.hpp"

#include <limits>

#include <fmt/format.h>

#include "device_logic/parameter_table.hpp"

namespace sreh::detail {
namespace {

bool is_text_type(ParamType t) { return t == ParamType::String || t == ParamType::OctetString; }

std::vector<uint8_t> encode_typed(const YamlReader& r, const YAML::Node& n, ParamType type, std::string_view what) {
  const auto [lo, hi] = wire_range(type);
  const int64_t raw = r.integer(n, fmt::format("{} ({})", what, type_name(type)), lo, hi);
  return encode_number(type, raw);
}

} // namespace

std::pair<int64_t, int64_t> wire_range(ParamType t) {
  switch (t) {
    case ParamType::UInt8: return {0, 0xFF};
    case ParamType::UInt16: return {0, 0xFFFF};
    case ParamType::UInt32: return {0, 0xFFFFFFFFLL};
    case ParamType::Int32: return {std::numeric_limits<int32_t>::min(), std::numeric_limits<int32_t>::max()};
    default: return {0, 0};
  }
}

std::vector<uint8_t> encode_untyped(int64_t v) {
  ParamType t = ParamType::Int32;
  if (v >= 0 && v <= 0xFF) t = ParamType::UInt8;
  else if (v >= 0 && v <= 0xFFFF) t = ParamType::UInt16;
  else if (v > std::numeric_limits<int32_t>::max()) t = ParamType::UInt32;
  return encode_number(t, v);
}

std::vector<uint8_t> encode_isdu_value(const YamlReader& r, const YAML::Node& value, uint16_t index, uint8_t subindex,
                                       std::string_view what) {
  const ParameterEntry* entry = find_parameter(index, subindex);
  if (value.IsSequence()) {
    const auto members = record_members(index);
    if (entry != nullptr || subindex != 0 || members.empty()) {
      r.fail(value, fmt::format("{}: a list of values is only allowed for a whole record (subindex 0)", what));
    }
    if (value.size() != members.size()) {
      r.fail(value, fmt::format("{}: record {} has {} members, got {} values", what, index, members.size(), value.size()));
    }
    std::vector<uint8_t> out;
    for (std::size_t i = 0; i < members.size(); ++i) {
      if (is_text_type(members[i]->type)) r.fail(value[i], fmt::format("{}: text members cannot be written as a list", what));
      const auto bytes = encode_typed(r, value[i], members[i]->type, fmt::format("{}[{}]", what, i));
      out.insert(out.end(), bytes.begin(), bytes.end());
    }
    return out;
  }
  if (!value.IsScalar()) r.fail(value, fmt::format("{}: expected a number or a text", what));
  if (entry != nullptr) {
    if (is_text_type(entry->type)) {
      const std::string s = value.Scalar();
      return {s.begin(), s.end()};
    }
    return encode_typed(r, value, entry->type, what);
  }
  if (subindex == 0 && !record_members(index).empty()) {
    r.fail(value, fmt::format("{}: index {} is a record: write one subindex, or a list of all {} member values", what,
                              index, record_members(index).size()));
  }
  // Not in the table: allowed, so that error paths (0x8011, 0x8012) can be tested.
  if (!r.is_quoted(value)) {
    if (auto v = parse_integer(value.Scalar())) {
      if (*v < std::numeric_limits<int32_t>::min() || *v > 0xFFFFFFFFLL) {
        r.fail(value, fmt::format("{}: {} does not fit 32 bits", what, value.Scalar()));
      }
      return encode_untyped(*v);
    }
  }
  const std::string s = value.Scalar();
  return {s.begin(), s.end()};
}

std::optional<int64_t> decode_isdu_number(uint16_t index, uint8_t subindex, std::span<const uint8_t> data) {
  const ParameterEntry* entry = find_parameter(index, subindex);
  if (entry != nullptr && !is_text_type(entry->type) && entry->type != ParamType::Record &&
      data.size() == wire_size(entry->type)) {
    return decode_number(entry->type, data);
  }
  if (data.empty() || data.size() > 8) return std::nullopt;
  return static_cast<int64_t>(be::read(data));
}

std::string decode_isdu_text(std::span<const uint8_t> data) {
  std::string s(data.begin(), data.end());
  while (!s.empty() && s.back() == '\0') s.pop_back();
  return s;
}

bool is_text_parameter(uint16_t index, uint8_t subindex) {
  const ParameterEntry* entry = find_parameter(index, subindex);
  return entry != nullptr && is_text_type(entry->type);
}

} // namespace sreh::detail
