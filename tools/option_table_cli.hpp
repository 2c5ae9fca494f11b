// Adds the options of a shared option table (sizing/option_table.hpp) to a
// CLI11 subcommand: "--" + name, list options comma separated.
#pragma once
#include <string>
#include <type_traits>

#include <CLI/CLI.hpp>

#include "sizing/option_table.hpp"

namespace sreh::tools {

template <class Options, class Table>
void add_table_options(CLI::App* cmd, const Table& table, Options& options) {
  for (const auto& spec : table) {
    const std::string flag = "--" + std::string(spec.name);
    const std::string help(spec.help);
    CLI::Option* opt = std::visit(
        [&](auto member) -> CLI::Option* {
          auto& field = options.*member;
          if constexpr (std::is_same_v<std::decay_t<decltype(field)>, bool>) {
            return cmd->add_flag(flag, field, help);
          } else {
          CLI::Option* o = cmd->add_option(flag, field, help);
          if constexpr (std::is_same_v<std::decay_t<decltype(field)>, std::vector<double>>) o->delimiter(',');
          return o;
          }
        },
        spec.field);
    if (spec.required) opt->required();
    if (spec.show_default) opt->capture_default_str();
  }
}

} // namespace sreh::tools
