// The studio's printable page (issue 37): `size --report`'s page for the
// state, with where it came from under the title (as every sizing report,
// sizing/report_provenance.hpp), so that page 1 holds the verdict and the inputs.
#include <fmt/format.h>

#include "sizing/report.hpp"
#include "sizing/report_provenance.hpp"
#include "studio/answer.hpp"

namespace sreh::studio {

std::string answer_report(const Json& state_in, const std::string& version) {
  const Json s = normalised_state(state_in);
  const sizing::SizingRequest rq = sizing_request(s);
  const sizing::SizingResult r = sizing::size(rq);
  io::Provenance p = sizing::size_provenance(rq, r.evaluation.load_gcm2);
  p.made_by = fmt::format("sreh-twin studio, project \"{}\" ({} parts); the same answer: {}", s["name"].get<std::string>(),
                          s["parts"].size(), size_command_line(s, "PROJECT.yaml"));
  p.version = version;
  return io::with_provenance(sizing::size_report_html(rq, r), p);
}

} // namespace sreh::studio
