// Subcommand registry for the sreh-twin CLI: each cmd_*.cpp adds its own
// subcommand with SREH_REGISTER_COMMAND, so commands live in small files.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace sreh::tools {

// Bad input (file, option, value): main prints "sreh-twin: <what>" and exits 2
// (interfaces.md).
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Runs `write`, the work behind an output option; a file that cannot be
// made fails as one InputError naming the option and its path
// ("--trace out/t.csv: ..."), the CLI's one-line error.
template <class Write>
decltype(auto) for_option(std::string_view option, const std::string& path, Write&& write) {
  try {
    return write();
  } catch (const std::runtime_error& e) {
    throw InputError(std::string(option) + " " + path + ": " + e.what());
  }
}

// A subcommand's setup: add the subcommand to `app`; its callback returns the
// process exit code through `exit_code`.
using CommandSetup = std::function<void(CLI::App& app, int& exit_code)>;

bool register_command(int order, CommandSetup setup);

// The command line this process was started with, shell-quoted where needed
// (reports show it so a run can be repeated).
const std::string& command_line();

} // namespace sreh::tools

#define SREH_CONCAT_INNER(a, b) a##b
#define SREH_CONCAT(a, b) SREH_CONCAT_INNER(a, b)
#define SREH_REGISTER_COMMAND(order, setup) \
  static const bool SREH_CONCAT(sreh_registered_, __LINE__) = ::sreh::tools::register_command(order, setup)
