// Subcommand registry for the sreh-twin CLI: each cmd_*.cpp adds its own
// subcommand with SREH_REGISTER_COMMAND, so commands live in small files.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <stdexcept>
#include <string>

namespace sreh::tools {

// Bad input (file, option, value): main prints "sreh-twin: <what>" and exits 2
// (interfaces.md).
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

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
