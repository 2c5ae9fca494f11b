// Where a report came from (issue 37): the command line or studio project
// that made it, the version, the date and the inputs (load and its inertia,
// mounting, supply, ambient, model file), shown at the top of the page
// under its title so that page 1 of a print holds them.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace sreh::io {

struct Provenance {
  std::string made_by;  // "sreh-twin size --load ...", or "sreh-twin studio, project ..."
  std::string version;  // "0.9.0"
  std::vector<std::pair<std::string, std::string>> inputs; // name, value
};

// What made the reports of this process: the command line and the version
// (tools/main.cpp sets them once; a library caller leaves them unset and
// its pages say "sreh-twin library").
void set_report_origin(const std::string& made_by, const std::string& version);
// A Provenance with the origin filled in and `inputs`.
Provenance report_provenance(std::vector<std::pair<std::string, std::string>> inputs);

// "2026-11-27 08:30 UTC": now, or SOURCE_DATE_EPOCH when set (reproducible
// builds' convention: byte-identical pages from the same inputs).
std::string report_date();

// A small table: made by, version, date, then the inputs (escaped).
std::string provenance_html(const Provenance& p);

// The page with provenance_html inserted after its first </h1> (or after
// <body> when it has none).
std::string with_provenance(const std::string& page, const Provenance& p);

} // namespace sreh::io
