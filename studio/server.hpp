// `sreh-twin studio` (issue 37): sizing in the browser. A small HTTP server
// on the loopback interface serving one page (web/, embedded in the binary,
// dygraphs-free: the plots are the reports' static SVGs) and the answers
// (answer.hpp) as JSON; offline, no CDN.
#pragma once
#include <functional>
#include <string>

namespace sreh::studio {

struct StudioOptions {
  std::string host = "127.0.0.1"; // loopback by default: the studio has no authentication
  int port = 8737;                // 0: any free port
  std::string project;            // PROJECT.yaml to open ("" a new project)
  std::string version;            // for the printable page's provenance
};

// Reads the project (ProjectError for a bad one), binds (std::runtime_error
// naming host and port when it cannot), calls `ready(url)` and serves until
// SIGINT / SIGTERM (io/interrupt.hpp).
void run_studio(const StudioOptions& options, const std::function<void(const std::string& url)>& ready);

} // namespace sreh::studio
