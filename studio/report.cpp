// The studio's printable page (issue 37): `size --report`'s page for the
// state (a cycle's: `size --cycle --report`'s), with where it came from
// under the title (as every sizing report, sizing/report_provenance.hpp),
// so that page 1 holds the verdict and the inputs.
#include <fmt/format.h>

#include "sizing/report.hpp"
#include "sizing/report_provenance.hpp"
#include "studio/answer.hpp"

namespace sreh::studio {

std::string answer_report(const Json& state_in, const std::string& version) {
  const Json s = normalised_state(state_in);
  io::Provenance p;
  std::string html;
  if (s["mode"] == "cycle") {
    const CycleSizing c = size_cycle_state(s);
    p = sizing::cycle_provenance(c.request);
    html = sizing::cycle_report_html(c.request, c.result, c.uncertainty ? &*c.uncertainty : nullptr);
  } else {
    const SingleSizing one = size_single_state(s);
    p = sizing::size_provenance(one.request, one.result.evaluation.load_gcm2);
    html = sizing::size_report_html(one.request, one.result, one.uncertainty ? &*one.uncertainty : nullptr);
  }
  p.made_by = fmt::format("sreh-twin studio, project \"{}\" ({} parts); the same answer: {}", s["name"].get<std::string>(),
                          s["parts"].size(),
                          size_command_line(s, "PROJECT.yaml") + (s["uncertainty"].get<bool>() ? " --uncertainty" : ""));
  p.version = version;
  return io::with_provenance(html, p);
}

} // namespace sreh::studio
