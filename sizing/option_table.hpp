// The options of `size` and `sweep` declared once (docs/style.md 5): the CLI adds
// them to its subcommands, the Python API takes them as keyword arguments
// (the long option with '-' as '_'), so both front ends fill the same
// structs and share the code path behind them.
#pragma once
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace sreh::sizing {

template <class Options>
using OptionField = std::variant<double Options::*, std::optional<double> Options::*, int Options::*,
                                 std::string Options::*, std::vector<double> Options::*, bool Options::*>; // bool: a flag

template <class Options>
struct OptionSpec {
  std::string_view name;  // long option without "--", e.g. "voltage-V"
  std::string_view help;
  OptionField<Options> field;
  bool required = false;
  bool show_default = false; // the CLI prints the default in --help
};

// "voltage-V" -> "voltage_V": the Python keyword of an option.
inline std::string keyword_of(std::string_view option) {
  std::string k(option);
  for (char& c : k) {
    if (c == '-') c = '_';
  }
  return k;
}

template <class Options>
const OptionSpec<Options>* find_option(std::span<const OptionSpec<Options>> table, std::string_view keyword) {
  for (const auto& spec : table) {
    if (keyword_of(spec.name) == keyword) return &spec;
  }
  return nullptr;
}

} // namespace sreh::sizing
