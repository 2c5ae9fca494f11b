#include "scenarios/comparison.hpp"

#include <cmath>

#include <fmt/format.h>

namespace sreh {

std::string Operand::str() const {
  if (var.empty()) return fmt::format("{:g}", number);
  if (offset == 0) return "$" + var;
  return fmt::format("${} {} {:g}", var, offset < 0 ? '-' : '+', std::abs(offset));
}

std::optional<double> Operand::value(const Variables& vars) const {
  if (var.empty()) return number;
  const auto it = vars.find(var);
  if (it == vars.end()) return std::nullopt;
  return it->second + offset;
}

Comparison Comparison::within(const Range& r) {
  Comparison c;
  c.terms.push_back(Term{Op::Within, r, {}});
  return c;
}

std::string Comparison::str() const {
  std::string s;
  for (const Term& t : terms) {
    if (!s.empty()) s += ", ";
    switch (t.op) {
      case Op::Within: s += t.range.str(); break;
      case Op::Eq: s += t.operand.str(); break;
      case Op::Ne: s += "ne " + t.operand.str(); break;
      case Op::Lt: s += "lt " + t.operand.str(); break;
      case Op::Gt: s += "gt " + t.operand.str(); break;
    }
  }
  return s;
}

bool Comparison::holds(double v, const Variables& vars, std::string* why) const {
  for (const Term& t : terms) {
    if (t.op == Op::Within) {
      if (!t.range.contains(v)) return false;
      continue;
    }
    const auto x = t.operand.value(vars);
    if (!x) {
      if (why) *why = fmt::format("${} was never saved", t.operand.var);
      return false;
    }
    const bool equal = std::abs(v - *x) <= tol;
    switch (t.op) {
      case Op::Eq: if (!equal) return false; break;
      case Op::Ne: if (equal) return false; break;
      case Op::Lt: if (!(v < *x)) return false; break;
      case Op::Gt: if (!(v > *x)) return false; break;
      case Op::Within: break;
    }
  }
  return true;
}

} // namespace sreh
