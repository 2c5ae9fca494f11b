// `sreh-twin completion bash` (issue 29): prints the bash completion script,
// so that `source <(sreh-twin completion bash)` (or a copy in
// /etc/bash_completion.d) completes commands, options and files.
#include <iostream>
#include <memory>
#include <string>

#include "tools/command.hpp"

namespace sreh::tools {
namespace {
constexpr const char* kBashCompletion =
#include "completion_script.inc"
    ;
} // namespace

SREH_REGISTER_COMMAND(90, [](CLI::App& app, int& exit_code) {
  auto shell = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("completion", "Print the shell completion script: source <(sreh-twin completion bash)");
  cmd->add_option("SHELL", *shell, "The shell: bash")->required()->check(CLI::IsMember({"bash"}));
  cmd->callback([shell, &exit_code] { // `shell` lives as long as the command line does
    std::cout << kBashCompletion;
    exit_code = 0;
  });
});

} // namespace sreh::tools
