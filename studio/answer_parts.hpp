// What the studio page shows around a sizing (answer.cpp): the verdict
// block of the reports, the plots, the ISDU writes only for a usable set,
// the limits in words and, for an infeasible answer, how far over each
// limit it is and the nearest feasible options (issue 37).
#pragma once
#include <string>

#include "sizing/limit_names.hpp"
#include "sizing/sizing.hpp"
#include "sizing/uncertainty.hpp"
#include "studio/project.hpp"

namespace sreh::studio {

using sizing::limit_in_words; // the limits' names in words (sizing/limit_names.hpp)

// How far over each limit of the figures the answer is (the "way out" table's rows).
Json figure_limits(const sizing::TraceFigures& figures, double required_thermal_margin_K);
// A parameter set as the page shows it: number, speed, acceleration, jerk.
Json set_json(const sizing::ParameterSetValues& set);

// Adds "verdict_html", "plots_html", "summary", "writes", "writes_ready"
// and, infeasible, "way_out" to `out`; with `uncertainty` (the switch) the
// verdict over every sample and "uncertainty_html" (the bands).
void add_answer_parts(Json& out, const Json& state, const sizing::SizingRequest& request, const sizing::SizingResult& result,
                      const sizing::UncertaintyResult* uncertainty = nullptr);

} // namespace sreh::studio
