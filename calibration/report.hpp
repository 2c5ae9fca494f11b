// `calibrate --report DIR` (issue 26): what the fit did, shown so that an
// engineer can judge it. Per log: the logged position against the twin's
// with the start card and with the fitted card, and their error over time
// (a wire count marked, the resolution of the logged position); the
// temperature when the log has it. Then the constants (start, fitted, 95 %
// interval, identified or why not) and their correlation, strongly
// correlated pairs marked. Only in builds with renders (SVG plots).
#pragma once
#include <filesystem>
#include <vector>

#include "calibration/fit.hpp"

namespace sreh {

bool calibration_reports_available();

// Writes DIR/index.html (atomically, the folder made if needed); returns its
// path. Replays every case twice (start and fitted card).
std::filesystem::path write_calibration_report(const std::filesystem::path& dir, const std::vector<FitCase>& cases,
                                               const ModelCard& start, const FitResult& fit);

} // namespace sreh
