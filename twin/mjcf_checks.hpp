// Checks and preparation of user MJCF load files before MuJoCo sees them
// (issue 12): MuJoCo accepts a negative, infinite or NaN mass on a body
// welded to the flange, or reports it later as an unrelated error.
#pragma once
#include <string>

#include <mujoco/mujoco.h>

namespace sreh {

// Replaces each <include file="F"/> by the children of F's <mujoco> root, F
// resolved against `dir` (the including file's folder, as MuJoCo documents;
// nested includes against their own file's folder). Throws
// std::invalid_argument "<origin>: ..." for a missing file or too deep nesting.
std::string expand_mjcf_includes(const std::string& text, const std::string& dir, const std::string& origin);

// Every mass, diaginertia, fullinertia and density attribute: finite, not
// negative, not subnormal; <inertial> mass and diaginertia above 0. Throws
// std::invalid_argument "<origin>:<line>: body '<name>': ...".
void check_mjcf_inertials(const std::string& text, const std::string& origin);

// The same rule on what MuJoCo computed (a finite density times a huge
// volume is an infinite mass): every body's mass and inertia finite, >= 0,
// not subnormal. Throws std::invalid_argument "<origin>: body '<name>': ...".
void check_compiled_inertials(const mjModel* model, const std::string& origin);

} // namespace sreh
