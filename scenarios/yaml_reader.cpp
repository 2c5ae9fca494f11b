#include "scenarios/yaml_reader.hpp"

#include "io/text.hpp"

#include <charconv>
#include <cmath>
#include <set>

#include <fmt/format.h>

namespace sreh::detail {

std::optional<int64_t> parse_integer(std::string_view s) {
  bool negative = false;
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) {
    negative = s[0] == '-';
    s.remove_prefix(1);
  }
  int base = 10;
  if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
    base = 16;
    s.remove_prefix(2);
  }
  if (s.empty()) return std::nullopt;
  uint64_t magnitude = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), magnitude, base);
  if (ec != std::errc{} || end != s.data() + s.size()) return std::nullopt;
  constexpr uint64_t kLimit = uint64_t{1} << 63;
  if (negative) {
    if (magnitude > kLimit) return std::nullopt;
    return magnitude == kLimit ? INT64_MIN : -static_cast<int64_t>(magnitude);
  }
  if (magnitude >= kLimit) return std::nullopt;
  return static_cast<int64_t>(magnitude);
}

std::optional<double> parse_number(std::string_view s) {
  if (auto i = parse_integer(s)) return static_cast<double>(*i);
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);
  if (s.empty() || !(std::isdigit(static_cast<unsigned char>(s[0])) || s[0] == '-' || s[0] == '.')) {
    return std::nullopt;
  }
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc{} || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::string join_path(std::string_view parent, std::string_view key) {
  if (parent.empty()) return std::string(key);
  return fmt::format("{}.{}", parent, key);
}

SourceLoc YamlReader::loc(const YAML::Node& node) const {
  SourceLoc l{file_, 0, 0};
  if (node.IsDefined()) {
    const YAML::Mark m = node.Mark();
    if (!m.is_null()) {
      l.line = m.line + 1; // yaml-cpp counts from 0
      l.column = m.column + 1;
    }
  }
  return l;
}

void YamlReader::fail(const YAML::Node& node, const std::string& message) const { fail(loc(node), message); }
void YamlReader::fail(const SourceLoc& l, const std::string& message) const { throw ScenarioError(l, message); }

namespace {
std::string describe(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Null: return "nothing";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Map: return "a mapping";
    case YAML::NodeType::Scalar: return fmt::format("'{}'", n.Scalar());
    default: return "nothing";
  }
}

std::string fmt_num(double v) { return fmt::format("{}", v); }
} // namespace

void YamlReader::check_map(const YAML::Node& node, std::string_view what,
                           const std::vector<std::string_view>& allowed) const {
  if (!node.IsMap()) fail(node, fmt::format("{}: expected a mapping, got {}", what, describe(node)));
  std::set<std::string> seen;
  for (const auto& kv : node) {
    if (!kv.first.IsScalar()) fail(kv.first, fmt::format("{}: keys must be plain names", what));
    const std::string key = kv.first.Scalar();
    bool known = false;
    for (auto a : allowed) known = known || key == a;
    if (!known) {
      std::string list;
      std::vector<std::string> names;
      for (auto a : allowed) {
        if (!list.empty()) list += ", ";
        list += a;
        names.emplace_back(a);
      }
      // Issue 39: "did you mean" by edit distance ("wait_untill" -> "wait_until").
      const std::string guess = io::closest_name(key, names);
      fail(kv.first, guess.empty() ? fmt::format("{}: unknown key '{}' (allowed: {})", what, key, list)
                                   : fmt::format("{}: unknown key '{}'; did you mean '{}'? (allowed: {})", what, key, guess, list));
    }
    if (!seen.insert(key).second) fail(kv.first, fmt::format("{}: key '{}' given twice", what, key));
  }
}

YAML::Node YamlReader::require(const YAML::Node& map, std::string_view key, std::string_view what) const {
  const YAML::Node n = map[std::string(key)];
  if (!n.IsDefined()) fail(map, fmt::format("{}: missing required key '{}'", what, key));
  return n;
}

double YamlReader::number(const YAML::Node& node, std::string_view what, double min, double max) const {
  if (!node.IsScalar() || is_quoted(node)) fail(node, fmt::format("{}: expected a number, got {}", what, describe(node)));
  const auto v = parse_number(node.Scalar());
  if (!v) fail(node, fmt::format("{}: expected a number, got '{}'", what, node.Scalar()));
  if (*v < min || *v > max) {
    fail(node, fmt::format("{}: {} is out of range [{}, {}]", what, node.Scalar(), fmt_num(min), fmt_num(max)));
  }
  return *v;
}

int64_t YamlReader::integer(const YAML::Node& node, std::string_view what, int64_t min, int64_t max) const {
  if (!node.IsScalar() || is_quoted(node)) fail(node, fmt::format("{}: expected an integer, got {}", what, describe(node)));
  const auto v = parse_integer(node.Scalar());
  if (!v) fail(node, fmt::format("{}: expected an integer, got '{}'", what, node.Scalar()));
  if (*v < min || *v > max) fail(node, fmt::format("{}: {} is out of range {}..{}", what, node.Scalar(), min, max));
  return *v;
}

bool YamlReader::boolean(const YAML::Node& node, std::string_view what) const {
  if (node.IsScalar() && !is_quoted(node)) {
    const std::string& s = node.Scalar();
    if (s == "1" || s == "true" || s == "True" || s == "TRUE") return true;
    if (s == "0" || s == "false" || s == "False" || s == "FALSE") return false;
  }
  fail(node, fmt::format("{}: expected 0/1 or true/false, got {}", what, describe(node)));
}

std::string YamlReader::text(const YAML::Node& node, std::string_view what) const {
  if (!node.IsScalar()) fail(node, fmt::format("{}: expected a text, got {}", what, describe(node)));
  return node.Scalar();
}

Range YamlReader::range(const YAML::Node& node, std::string_view what, double min, double max, bool integers,
                        double tol) const {
  auto one = [&](const YAML::Node& n) {
    return integers ? static_cast<double>(integer(n, what, static_cast<int64_t>(min), static_cast<int64_t>(max)))
                    : number(n, what, min, max);
  };
  if (node.IsSequence()) {
    if (node.size() != 2) fail(node, fmt::format("{}: a range is [min, max], got {} values", what, node.size()));
    Range r{one(node[0]), one(node[1]), false};
    if (r.min > r.max) fail(node, fmt::format("{}: range [{}, {}] has min > max", what, fmt_num(r.min), fmt_num(r.max)));
    return r;
  }
  if (!node.IsScalar()) fail(node, fmt::format("{}: expected a number or [min, max], got {}", what, describe(node)));
  const double v = one(node);
  return Range{v - tol, v + tol, true};
}

bool YamlFieldSource::has(std::string_view key) const { return static_cast<bool>(map_[std::string(key)]); }
double YamlFieldSource::number(std::string_view key, double lo, double hi) const {
  return r_.number(map_[std::string(key)], path(key), lo, hi);
}
int64_t YamlFieldSource::integer(std::string_view key, int64_t lo, int64_t hi) const {
  return r_.integer(map_[std::string(key)], path(key), lo, hi);
}
bool YamlFieldSource::boolean(std::string_view key) const { return r_.boolean(map_[std::string(key)], path(key)); }
void YamlFieldSource::fail(std::string_view key, const std::string& message) const { r_.fail(map_[std::string(key)], message); }

} // namespace sreh::detail
