#include "sizing/report_provenance.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "io/atomic_file.hpp"
#include "io/output_path.hpp"
#include "twin/load_builder.hpp"

namespace sreh::sizing {
namespace {

std::string mounting_text(double tilt_deg) {
  if (tilt_deg == 0) return "vertical axis";
  if (tilt_deg == 90) return "horizontal axis";
  return fmt::format("axis tilted {} deg from vertical", tilt_deg);
}

// The inputs every sizing shares: the world.
std::vector<std::pair<std::string, std::string>> world_inputs(const WorldSetup& w, const std::string& load) {
  return {{"load", load},
          {"mounting", mounting_text(w.mounting_tilt_deg)},
          {"supply / ambient", fmt::format("{} V / {} degC", w.supply.voltage_V, w.thermal.ambient_C)},
          {"model file", w.model_file.empty() ? std::string("the built-in model card") : w.model_file}};
}

} // namespace

io::Provenance size_provenance(const SizingRequest& rq, double load_gcm2) {
  auto in = world_inputs(rq.world, fmt::format("{}: {:.1f} g cm^2 about the axis", describe_load(rq.world.load), load_gcm2));
  in.push_back({"move", fmt::format("{} deg back and forth, dwell {} s, tolerance {} deg", rq.angle_deg, rq.dwell_s,
                                    rq.settling.tolerance_deg)});
  if (rq.max_positioning_ms) in.push_back({"required", fmt::format("positioning within {} ms", *rq.max_positioning_ms)});
  if (rq.max_cycle_ms) in.push_back({"required", fmt::format("cycle within {} ms", *rq.max_cycle_ms)});
  return io::report_provenance(std::move(in));
}

io::Provenance cycle_provenance(const CycleRequest& rq) {
  auto in = world_inputs(rq.world, fmt::format("{} at the start of each repetition", describe_load(rq.world.load)));
  in.push_back({"cycle", fmt::format("{}: {} segments, {} repetitions simulated", rq.file, rq.segments.size(), rq.cycles)});
  return io::report_provenance(std::move(in));
}

io::Provenance sweep_provenance(const SweepRequest& rq) {
  auto in = world_inputs(rq.base.world, fmt::format("{} g cm^2 (the grid)", fmt::join(rq.loads_gcm2, ", ")));
  in[2].second = fmt::format("{} V / {} degC", fmt::join(rq.voltages_V, ", "), rq.base.world.thermal.ambient_C);
  in.push_back({"moves", fmt::format("{} deg, dwell {} s", fmt::join(rq.angles_deg, ", "), rq.base.dwell_s)});
  return io::report_provenance(std::move(in));
}

std::filesystem::path write_report_page(const std::filesystem::path& dir, const std::string& html, const io::Provenance& p) {
  io::make_output_folder(dir.string());
  const std::filesystem::path index = dir / "index.html";
  io::write_file_atomic(index.string(), [&](std::ostream& out) { out << io::with_provenance(html, p); });
  return index;
}

} // namespace sreh::sizing
