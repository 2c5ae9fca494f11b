// What to say when CLI11 refuses a command line (issue 29): the nearest
// option to a mistyped one, and a value given with its unit ("90deg") told
// to drop the unit the option's name already carries.
#pragma once
#include <string>

#include <CLI/CLI.hpp>

namespace sreh::tools {

// A better one-line message for `error`, or "" to keep CLI11's own.
// `argv` as main got it: the first argument names the subcommand.
std::string cli_hint(const CLI::App& app, const CLI::ParseError& error, int argc, char** argv);

} // namespace sreh::tools
