// What the studio page shows around a sizing (answer.cpp): the verdict
// block of the reports, the plots, the ISDU writes only for a usable set,
// the limits in words and, for an infeasible answer, how far over each
// limit it is and the nearest feasible options (issue 37).
#pragma once
#include <string>

#include "sizing/sizing.hpp"
#include "studio/project.hpp"

namespace sreh::studio {

// A limit's name in words ("torque_at_speed" -> "peak torque at speed").
std::string limit_in_words(const std::string& limit);

// Adds "verdict_html", "plots_html", "summary", "writes", "writes_ready"
// and, infeasible, "way_out" to `out`.
void add_answer_parts(Json& out, const Json& state, const sizing::SizingRequest& request, const sizing::SizingResult& result);

} // namespace sreh::studio
