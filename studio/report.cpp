// The studio's printable page (issue 37): `size --report`'s page for the
// state, with where it came from under the title (io/provenance.hpp), so
// that page 1 holds the verdict and the inputs.
#include <fmt/format.h>

#include "io/provenance.hpp"
#include "sizing/report.hpp"
#include "studio/answer.hpp"

namespace sreh::studio {

std::string answer_report(const Json& state_in, const std::string& version) {
  const Json s = normalised_state(state_in);
  const Json load = load_panel(s);
  const sizing::SizingRequest rq = sizing_request(s);
  const sizing::SizingResult r = sizing::size(rq);
  io::Provenance p;
  p.made_by = fmt::format("sreh-twin studio, project \"{}\"; the same answer: {}", s["name"].get<std::string>(),
                          size_command_line(s, "PROJECT.yaml"));
  p.version = version;
  p.inputs = {
      {"load", fmt::format("{} ({} parts): {:.1f} g cm^2 about the axis, {:.3f} kg", s["name"].get<std::string>(), s["parts"].size(),
                           load["inertia_gcm2"].get<double>(), load["mass_kg"].get<double>())},
      {"mounting", fmt::format("axis tilted {} deg from vertical", s["mounting_tilt_deg"].get<double>())},
      {"supply / ambient", fmt::format("{} V / {} degC", rq.world.supply.voltage_V, rq.world.thermal.ambient_C)},
      {"move", fmt::format("{} deg back and forth, dwell {} s, tolerance {} deg", rq.angle_deg, rq.dwell_s,
                           rq.settling.tolerance_deg)},
      {"required", rq.max_positioning_ms ? fmt::format("positioning within {} ms", *rq.max_positioning_ms)
                   : rq.max_cycle_ms     ? fmt::format("cycle within {} ms", *rq.max_cycle_ms)
                                         : std::string("none (the fastest feasible set)")},
      {"model file", rq.world.model_file.empty() ? std::string("the built-in model card") : rq.world.model_file}};
  return io::with_provenance(sizing::size_report_html(rq, r), p);
}

} // namespace sreh::studio
