// `sreh-twin studio [--http 127.0.0.1:PORT] [PROJECT.yaml]` (issue 37):
// sizing in the browser, on the loopback interface by default; prints the
// URL to open and serves until Ctrl-C. docs/studio.md.
#if SREH_WITH_STUDIO
#include <iostream>
#include <memory>

#include "serve/server.hpp"
#include "studio/project.hpp"
#include "studio/server.hpp"
#include "tools/command.hpp"

namespace sreh::tools {
namespace {

struct StudioArgs {
  std::string http = "127.0.0.1:8737";
  std::string project;
};

int studio_command(const StudioArgs& a) {
  studio::StudioOptions o;
  try {
    const serve::Endpoint e = serve::parse_endpoint(a.http, "--http");
    o.host = e.host;
    o.port = e.port;
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
  o.project = a.project;
  o.version = SREH_VERSION;
  try {
    studio::run_studio(o, [](const std::string& url) {
      std::cout << "sreh-twin studio: open " << url << " in a browser (Ctrl-C stops it)" << std::endl;
    });
  } catch (const studio::ProjectError& e) {
    throw InputError(e.what());
  } catch (const std::runtime_error& e) { // cannot listen
    throw InputError(e.what());
  }
  return 0;
}

} // namespace

SREH_REGISTER_COMMAND(35, [](CLI::App& app, int& exit_code) {
  auto a = std::make_shared<StudioArgs>();
  CLI::App* cmd = app.add_subcommand("studio", "Size in the browser: build the load from parts, set the move, read the verdict, "
                                               "compare options, export (a local web page; docs/studio.md)");
  cmd->add_option("--http", a->http, "Listen address HOST:PORT (PORT 0: any free port); loopback unless you choose otherwise")
      ->default_val("127.0.0.1:8737");
  cmd->add_option("project", a->project, "Project file to open (as the studio exports it, or a load file of parts)")
      ->check(CLI::ExistingFile);
  cmd->callback([a, &exit_code] { exit_code = studio_command(*a); });
});

} // namespace sreh::tools
#endif
