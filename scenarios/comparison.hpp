// Numeric checks in scenarios: a number, a range, or comparisons (eq, ne,
// lt, gt) against a number or a value remembered earlier in the run
// (`save_as` / `save`, written `$NAME` or `$NAME + 1440`). Plain structs;
// parsing is in comparison_parser.cpp, evaluation needs the run's variables.
#pragma once
#include <map>
#include <optional>
#include <cstddef>
#include <string>
#include <vector>


namespace sreh {

// A closed interval. A plain number in a scenario becomes [x - tol, x + tol]
// with `exact` set (tol is 0 for integers, half a wire count for degrees).
struct Range {
  double min = 0;
  double max = 0;
  bool exact = false; // written as one number, not [min, max]
  bool contains(double v) const { return v >= min && v <= max; }
  std::string str() const; // "90" or "[89.9, 90.1]"
};

// Values remembered during a run, by name.
using Variables = std::map<std::string, double>;

// A number, or $NAME plus an optional offset.
struct Operand {
  double number = 0;
  std::string var; // empty: a plain number
  double offset = 0;
  std::string str() const;                                // "90", "$before + 1440"
  std::optional<double> value(const Variables& vars) const; // nullopt: $NAME not saved (yet)
};

struct Comparison {
  enum class Op { Within, Eq, Ne, Lt, Gt };
  struct Term {
    Op op = Op::Within;
    Range range;     // Within
    Operand operand; // the others
  };
  std::vector<Term> terms; // all must hold
  double tol = 0;          // Eq / Ne: |v - x| <= tol counts as equal (half a wire count for degrees)

  static Comparison within(const Range& r);
  std::string str() const; // "[89.9, 90.1]", "ne $before", "gt 3, lt 5"
  // Whether `v` satisfies every term; `why` names an unsaved variable.
  bool holds(double v, const Variables& vars, std::string* why = nullptr) const;
};

} // namespace sreh
