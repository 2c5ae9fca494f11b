// sreh-twin: the command line of the SREH-50-IOL digital twin.
// Exit codes (interfaces.md, README): 0 ok, 1 expectation failed /
// infeasible, 2 bad input (file, option, limit), 3 internal error (a bug),
// 130 / 143 interrupted by SIGINT / SIGTERM (temporary files removed).
#include <algorithm>
#include <exception>
#include <iostream>
#include <vector>

#include "io/interrupt.hpp"
#include "io/provenance.hpp"
#include "io/output_path.hpp"
#include "io/text.hpp"
#include "tools/cli_hints.hpp"
#include "tools/command.hpp"
#include "twin/models_dir.hpp"

namespace sreh::tools {
namespace {
std::vector<std::pair<int, CommandSetup>>& registry() {
  static std::vector<std::pair<int, CommandSetup>> commands;
  return commands;
}
} // namespace

std::string& command_line_storage() {
  static std::string line;
  return line;
}

void set_command_line(int argc, char** argv) {
  std::string& line = command_line_storage();
  for (int i = 0; i < argc; ++i) {
    std::string a = i == 0 ? std::string("sreh-twin") : std::string(argv[i]);
    const bool plain = !a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_./=:,+@%") == std::string::npos;
    if (!plain) {
      std::string q = "'";
      for (char c : a) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
      a = q + "'";
    }
    line += (i ? " " : "") + a;
  }
}

const std::string& command_line() { return command_line_storage(); }

bool register_command(int order, CommandSetup setup) {
  registry().emplace_back(order, std::move(setup));
  return true;
}
} // namespace sreh::tools

namespace {
constexpr const char* kExitCodes =
    "Exit codes: 0 all held / feasible, 1 a check failed / infeasible, 2 bad input (file, option or limit; "
    "one line on stderr), 3 internal error (a bug: please report), 130 / 143 interrupted by SIGINT / SIGTERM "
    "(no output written, temporary files removed; serve stops cleanly with 0, see serve --help).";

// No command, or one that does not exist (issue 29): say which there are.
// Empty when the first argument is an option or a known command.
std::string command_problem(const CLI::App& app, int argc, char** argv) {
  std::string names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    names += (names.empty() ? "" : ", ") + sub->get_name();
  }
  if (argc < 2) return "give a command: " + names + " (sreh-twin COMMAND --help for its options)";
  const std::string first = argv[1];
  if (first.empty() || first[0] == '-') return {};
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    if (sub->get_name() == first) return {};
  }
  const std::string guess = sreh::tools::command_hint(app, first);
  return "unknown command '" + first + "'; " + (guess.empty() ? "" : "did you mean " + guess + "? ") + "the commands are " + names;
}

// Error messages echo user input: one line, control characters escaped.
int fail(int code, const std::string& what) {
  std::cerr << "sreh-twin: " << sreh::io::escape_control(what) << "\n";
  return code;
}
} // namespace

int main(int argc, char** argv) {
  using namespace sreh::tools;
  set_command_line(argc, argv);
  sreh::io::set_report_origin(command_line(), SREH_VERSION); // the reports say where they came from (issue 37)
  CLI::App app{"sreh-twin: digital twin of the Afag SREH-50-IOL smart rotary module"};
  app.footer(kExitCodes);
  // --version: the release and where this installation finds its models (issue 13).
  app.set_version_flag("--version", [] {
    std::string models;
    try {
      models = sreh::models_dir();
    } catch (const std::exception& e) {
      models = std::string("not found: ") + e.what();
    }
    return std::string("sreh-twin ") + SREH_VERSION + " (models: " + models + ")";
  });
  app.require_subcommand(1);
  sreh::io::install_interrupt_handlers();
  int exit_code = 0;
  auto commands = registry();
  std::stable_sort(commands.begin(), commands.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& [order, setup] : commands) setup(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    if (const std::string problem = command_problem(app, argc, argv); !problem.empty()) return fail(2, problem);
    if (const std::string hint = cli_hint(app, e, argc, argv); !hint.empty()) return fail(2, hint);
    return fail(2, e.what());
  } catch (const sreh::io::Interrupted& e) {
    return fail(e.exit_code(), e.what());
  } catch (const InputError& e) {
    if (const int s = sreh::io::interrupt_signal()) return fail(128 + s, sreh::io::Interrupted(s).what());
    return fail(2, e.what());
  } catch (const sreh::io::PathError& e) {
    return fail(2, e.what());
  } catch (const std::exception& e) {
    // A signal also stops child processes (ffmpeg): their failure is the interrupt.
    if (const int s = sreh::io::interrupt_signal()) return fail(128 + s, sreh::io::Interrupted(s).what());
    return fail(3, std::string("internal error: ") + e.what());
  }
  return exit_code;
}
