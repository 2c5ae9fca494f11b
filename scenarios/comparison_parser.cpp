#include "scenarios/comparison_parser.hpp"

#include <cctype>

#include <fmt/format.h>

namespace sreh::detail {
namespace {

bool name_ok(std::string_view s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  }
  return true;
}

std::string trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return std::string(s);
}

bool is_reference(const YAML::Node& n) { return n.IsScalar() && !n.Scalar().empty() && n.Scalar()[0] == '$'; }

// "$NAME", "$NAME + 1440", "$NAME - 0.5".
Operand read_reference(const YamlReader& r, const YAML::Node& n, std::string_view what,
                       const std::set<std::string>& saved) {
  const std::string text = n.Scalar().substr(1);
  const auto op = text.find_first_of("+-");
  Operand o;
  o.var = trim(std::string_view(text).substr(0, op));
  if (!name_ok(o.var)) r.fail(n, fmt::format("{}: '{}' is not $NAME or $NAME + NUMBER", what, n.Scalar()));
  if (!saved.count(o.var)) {
    r.fail(n, fmt::format("{}: ${} is not saved before this step (save_as / save)", what, o.var));
  }
  if (op != std::string::npos) {
    const auto v = parse_number(trim(std::string_view(text).substr(op + 1)));
    if (!v) r.fail(n, fmt::format("{}: '{}' is not $NAME or $NAME + NUMBER", what, n.Scalar()));
    o.offset = text[op] == '-' ? -*v : *v;
  }
  return o;
}

Operand read_operand(const YamlReader& r, const YAML::Node& n, std::string_view what, const NumberSpec& spec,
                     const std::set<std::string>& saved) {
  if (is_reference(n)) return read_reference(r, n, what, saved);
  Operand o;
  o.number = spec.integers ? static_cast<double>(r.integer(n, what, static_cast<int64_t>(spec.min),
                                                           static_cast<int64_t>(spec.max)))
                           : r.number(n, what, spec.min, spec.max);
  return o;
}

} // namespace

Comparison read_comparison(const YamlReader& r, const YAML::Node& n, std::string_view what, const NumberSpec& spec,
                           const std::set<std::string>& saved) {
  Comparison c;
  c.tol = spec.tol;
  if (is_reference(n)) {
    c.terms.push_back(Comparison::Term{Comparison::Op::Eq, {}, read_reference(r, n, what, saved)});
    return c;
  }
  if (!n.IsMap()) return Comparison::within(r.range(n, what, spec.min, spec.max, spec.integers, spec.tol));
  r.check_map(n, what, {"eq", "ne", "lt", "gt"});
  if (n.size() == 0) r.fail(n, fmt::format("{}: empty comparison (give eq, ne, lt or gt)", what));
  for (const auto& kv : n) {
    const std::string key = kv.first.Scalar();
    const Comparison::Op op = key == "eq" ? Comparison::Op::Eq
                              : key == "ne" ? Comparison::Op::Ne
                              : key == "lt" ? Comparison::Op::Lt
                                            : Comparison::Op::Gt;
    c.terms.push_back(Comparison::Term{op, {}, read_operand(r, kv.second, join_path(what, key), spec, saved)});
  }
  return c;
}

std::string read_variable_name(const YamlReader& r, const YAML::Node& n, std::string_view what) {
  const std::string name = r.text(n, what);
  if (!name_ok(name)) {
    r.fail(n, fmt::format("{}: '{}' is not a name (a letter or _, then letters, digits, _)", what, name));
  }
  return name;
}

} // namespace sreh::detail
