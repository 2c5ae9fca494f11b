// Where a sizing report came from (issue 37): the command line, version and
// date (io/provenance.hpp) and the inputs of a single move, a cycle or a
// sweep, at the top of the page so that page 1 of a print holds them.
#pragma once
#include <filesystem>
#include <string>

#include "io/provenance.hpp"
#include "sizing/cycle.hpp"
#include "sizing/sizing.hpp"
#include "sizing/sweep.hpp"

namespace sreh::sizing {

// The inputs: load (described, and its inertia), mounting, supply, ambient,
// model file, the move or cycle.
io::Provenance size_provenance(const SizingRequest& request, double load_gcm2);
io::Provenance cycle_provenance(const CycleRequest& request);
io::Provenance sweep_provenance(const SweepRequest& request);

// `html` with the provenance under its title, written as dir/index.html
// atomically (the folder made if needed).
std::filesystem::path write_report_page(const std::filesystem::path& dir, const std::string& html, const io::Provenance& p);

} // namespace sreh::sizing
