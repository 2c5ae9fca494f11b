// What to say when CLI11 refuses a command line (issue 29, 39): the nearest
// command or option to a mistyped one, a value that is not a number in the
// option's unit ("expected a number in deg, e.g. 90"), and a value given
// with its unit ("90deg") told to drop the unit the option's name carries.
#pragma once
#include <string>

#include <CLI/CLI.hpp>

namespace sreh::tools {

// A better one-line message for `error`, or "" to keep CLI11's own.
// `argv` as main got it: the first argument names the subcommand.
std::string cli_hint(const CLI::App& app, const CLI::ParseError& error, int argc, char** argv);
// The command `given` most likely meant ("sise" -> "size"), or "".
std::string command_hint(const CLI::App& app, const std::string& given);

} // namespace sreh::tools
