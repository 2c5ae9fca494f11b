// HTML reports of a sizing and of a sweep (issue 8): one self-contained
// index.html each (inline SVG from renders/svg_plot, no scripts), written
// atomically. Available when the build has renders (SREH_WITH_RENDER);
// otherwise the writers throw std::runtime_error saying so.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <optional>

#include "sizing/cycle.hpp"
#include "sizing/sizing.hpp"
#include "sizing/sweep.hpp"

namespace sreh::sizing {

struct UncertaintyResult; // sizing/uncertainty.hpp
struct SettlingSpread;    // sizing/settling_spread.hpp

bool reports_available();

// The result's evaluation should carry its trace (SizingRequest::keep_trace)
// for the position / velocity / torque plots.
// With `uncertainty` (size --uncertainty, issue 26) the page also shows the
// bands: a table, and shaded bands in the torque and temperature plots;
// the verdict block's badge is then the verdict over every sample (issue
// 35). With `spread` the settling over targets a few counts apart.
std::string size_report_html(const SizingRequest& request, const SizingResult& result,
                             const UncertaintyResult* uncertainty = nullptr, const SettlingSpread* spread = nullptr);
std::filesystem::path write_size_report(const std::filesystem::path& dir, const SizingRequest& request,
                                        const SizingResult& result, const UncertaintyResult* uncertainty = nullptr,
                                        const SettlingSpread* spread = nullptr);

// The cycle's report (cycle_report.cpp): numbers, sets, segments, the
// speed-torque plane with the envelope, time per segment, temperature.
std::string cycle_report_html(const CycleRequest& request, const CycleResult& result,
                              const UncertaintyResult* uncertainty = nullptr);
std::filesystem::path write_cycle_report(const std::filesystem::path& dir, const CycleRequest& request,
                                         const CycleResult& result, const UncertaintyResult* uncertainty = nullptr);

// Temperature vs time from ambient under the mean loss, with the 70 degC
// warning, the 75 degC trip and the required margin (both reports); with
// `steady_band_C` the steady temperature's range over the sampled models
// shaded (size --uncertainty).
std::string temperature_plot(double mean_loss_W, double ambient_C, double thermal_margin_K,
                             const std::optional<double>& time_to_trip_s, const ThermalConstants& constants,
                             const UncertaintyResult* steady_band = nullptr);

// Target times for the inverse plot when none are given: nice values
// spanning the feasible positioning times of the grid.
std::vector<double> default_targets_s(const SweepResult& result);

std::string sweep_report_html(const SweepRequest& request, const SweepResult& result,
                              const std::vector<double>& targets_s);
std::filesystem::path write_sweep_report(const std::filesystem::path& dir, const SweepRequest& request,
                                         const SweepResult& result, const std::vector<double>& targets_s);

} // namespace sreh::sizing
