#include "studio/cycle_answer.hpp"

#include <algorithm>

#include "io/cpus.hpp"
#include "io/figures.hpp"
#include "renders/figure.hpp"
#include "sizing/cycle_output.hpp"
#include "sizing/output.hpp"
#include "sizing/report.hpp"
#include "sizing/report_parts.hpp"
#include "studio/answer_parts.hpp"
#include "twin/model_card.hpp"

namespace sreh::studio {

sizing::CycleRequest cycle_request(const Json& state) {
  try {
    sizing::CycleRequest rq = sizing::parse_cycle_text(cycle_file_yaml(state), "project", ".");
    rq.keep_trace = true; // as `size --cycle --report`: the plots need the trace
    return rq;
  } catch (const sizing::SizingInputError& e) {
    throw ProjectError(e.what());
  }
}

CycleSizing size_cycle_state(const Json& state, const std::function<void()>& on_simulation) {
  CycleSizing c{cycle_request(state), {}, std::nullopt};
  c.request.on_simulation = on_simulation;
  c.request.threads = io::usable_cpus(); // as size --cycle
  c.result = sizing::size_cycle(c.request);
  if (normalised_state(state)["uncertainty"].get<bool>()) {
    c.uncertainty = sizing::cycle_uncertainty(c.request, sizing::plan_sets(c.request), c.result.settings,
                                              default_model_card(), c.result.evaluation, kUncertaintySamples,
                                              kUncertaintySeed, io::usable_cpus());
  }
  return c;
}

void add_cycle_answer(Json& out, const Json& state, const std::function<void()>& on_simulation) {
  const CycleSizing c = size_cycle_state(state, on_simulation);
  const sizing::CycleRequest& rq = c.request;
  const sizing::CycleEvaluation& e = c.result.evaluation;
  const sizing::UncertaintyResult* u = c.uncertainty ? &*c.uncertainty : nullptr;
  Json j = sizing::cycle_to_json(rq, c.result, u);
  io::round_figures(j);
  out["size"] = j;
  const bool feasible = u ? u->feasible_worst_case : e.feasible;
  double speed_dps = 0, load_gcm2 = 0; // as the cycle report's verdict block: the fastest set, the heaviest load moved
  for (const sizing::ParameterSetValues& set : e.sets) speed_dps = std::max(speed_dps, set.tidy.speed_dps);
  for (const sizing::SegmentResult& s : e.segments) {
    if (s.kind == "move") load_gcm2 = std::max(load_gcm2, s.load_gcm2);
  }
  out["verdict_html"] = sizing::report_parts::verdict_block(
      {&e, e.feasible, e.binding_limit, rq.thermal_margin_K, rq.world.thermal.ambient_C, speed_dps, load_gcm2, u});
  if (u) {
    const sizing::WorstMove w = sizing::worst_move(e);
    out["uncertainty_html"] = sizing::report_parts::uncertainty_section(
        *u, {w.positioning_s, w.settling_s, e.peak_torque_Nm, e.steady_temperature_C, e.cycle_s});
  }
  std::string plots;
  if (!e.trace.empty()) plots += report::figure(sizing::report_parts::position_plot("studio-position", e.trace), false);
  plots += sizing::temperature_plot(e.mean_loss_W, rq.world.thermal.ambient_C, rq.thermal_margin_K, e.time_to_trip_s,
                                    rq.world.module.thermal);
  out["plots_html"] = plots;
  Json sets = Json::array();
  for (const sizing::ParameterSetValues& set : e.sets) sets.push_back(set_json(set));
  out["summary"] = {{"feasible", feasible},
                    {"binding_limit", e.binding_limit},
                    {"binding_limit_words", limit_in_words(e.binding_limit)},
                    {"reason", e.reason},
                    {"set", sets.empty() ? Json() : sets[0]},
                    {"sets", sets}};
  out["writes_ready"] = feasible;
  out["writes"] = Json::array();
  if (feasible) {
    for (const sizing::IsduWrite& w : sizing::all_writes(e)) out["writes"].push_back(sizing::isdu_write_line(w));
  } else {
    out["way_out"] = {{"limits", figure_limits(e, rq.thermal_margin_K)}, {"options", Json::array()}};
  }
}

} // namespace sreh::studio
