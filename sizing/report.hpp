// HTML reports of a sizing and of a sweep (issue 8): one self-contained
// index.html each (inline SVG from renders/svg_plot, no scripts), written
// atomically. Available when the build has renders (SREH_WITH_RENDER);
// otherwise the writers throw std::runtime_error saying so.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "sizing/sizing.hpp"
#include "sizing/sweep.hpp"

namespace sreh::sizing {

bool reports_available();

// The result's evaluation should carry its trace (SizingRequest::keep_trace)
// for the position / velocity / torque plots.
std::string size_report_html(const SizingRequest& request, const SizingResult& result);
std::filesystem::path write_size_report(const std::filesystem::path& dir, const SizingRequest& request,
                                        const SizingResult& result);

// Target times for the inverse plot when none are given: nice values
// spanning the feasible positioning times of the grid.
std::vector<double> default_targets_s(const SweepResult& result);

std::string sweep_report_html(const SweepRequest& request, const SweepResult& result,
                              const std::vector<double>& targets_s);
std::filesystem::path write_sweep_report(const std::filesystem::path& dir, const SweepRequest& request,
                                         const SweepResult& result, const std::vector<double>& targets_s);

} // namespace sreh::sizing
