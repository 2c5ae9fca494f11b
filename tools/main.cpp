// sreh-twin: the command line of the SREH-50-IOL digital twin.
// Exit codes (interfaces.md): 0 ok, 1 expectation failed / infeasible, 2 bad input.
#include <algorithm>
#include <exception>
#include <iostream>
#include <vector>

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

int main(int argc, char** argv) {
  using namespace sreh::tools;
  set_command_line(argc, argv);
  CLI::App app{"sreh-twin: digital twin of the Afag SREH-50-IOL smart rotary module"};
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
    std::cerr << "sreh-twin: " << e.what() << "\n";
    return 2;
  } catch (const InputError& e) {
    std::cerr << "sreh-twin: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "sreh-twin: internal error: " << e.what() << "\n";
    return 3;
  }
  return exit_code;
}
