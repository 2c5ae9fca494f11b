// An assembly load (issue 28) as MJCF: one body per part under the body
// "load", placed at the part's `at_m` and turned by its `rpy_deg`, holding
// the part's shape centred on it (a mesh's or MJCF file's own origin).
#pragma once
#include <string>

#include "twin/mjcf_load.hpp"
#include "twin/specs.hpp"

namespace sreh {

// Body name of part k inside the body "load".
std::string part_body_name(std::size_t k);

// The assembly's body, assets and mesh files. Throws std::invalid_argument
// "<part origin>: ..." for bad dimensions or files.
LoadXml assembly_xml(const AssemblyLoad& load, const std::string& module_assets);

// "disk", "ring", ... : the part's shape key.
std::string part_kind(const PartShape& shape);

} // namespace sreh
