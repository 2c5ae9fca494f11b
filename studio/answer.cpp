#include "studio/answer.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "device_logic/units.hpp"
#include "io/figures.hpp"
#include "scenarios/load_file.hpp"
#include "scenarios/source_loc.hpp"
#include "sizing/cycle_output.hpp"
#include "sizing/output.hpp"
#include "sizing/size_csv.hpp"
#include "studio/answer_parts.hpp"
#include "studio/cycle_answer.hpp"
#include "io/cpus.hpp"
#include "sizing/uncertainty.hpp"
#include "twin/model_card.hpp"
#include "twin/load_builder.hpp"
#include "twin/load_figures.hpp"

namespace sreh::studio {
namespace {

Json part_json(const PartFigures& p, double scale, double total_inertia) {
  const double j = kgm2_to_gcm2(p.inertia_kgm2) / scale;
  return {{"name", p.name}, {"shape", p.shape}, {"mass_kg", p.mass_kg / scale}, {"inertia_gcm2", j},
          {"share", total_inertia > 0 ? j / total_inertia : 0.0},
          {"com_m", {p.com_m[0], p.com_m[1], p.com_m[2]}}};
}

} // namespace

LoadFileContents parsed_load(const Json& state, double mass_scale) {
  try {
    return parse_load_text(load_yaml(state, mass_scale), "project", ".");
  } catch (const ScenarioError& e) {
    throw ProjectError(e.message());
  }
}

LoadFigures load_figures_of(const Json& state, double& mass_scale) {
  mass_scale = 1.0;
  try {
    return load_figures(parsed_load(state).load);
  } catch (const std::invalid_argument& first) {
    mass_scale = kOverLimitScale;
    LoadFigures f;
    try {
      f = load_figures(parsed_load(state, mass_scale).load);
    } catch (const std::invalid_argument&) {
      throw ProjectError(first.what());
    }
    if (within_load_limit(kgm2_to_gcm2(f.inertia_kgm2) / mass_scale)) throw ProjectError(first.what());
    return f;
  }
}

Json load_panel(const Json& state_in) {
  const Json s = normalised_state(state_in);
  const double tilt = s["mounting_tilt_deg"].get<double>();
  Json out = {{"max_gcm2", max_load_gcm2()}, {"mass_kg", 0.0},       {"inertia_gcm2", 0.0}, {"com_m", {0.0, 0.0, 0.0}},
              {"com_radius_m", 0.0},        {"gravity_torque_Nm", 0.0}, {"parts", Json::array()}, {"over_by_gcm2", 0.0}};
  if (s["parts"].empty()) return out;
  double scale = 1.0;
  const LoadFigures f = load_figures_of(s, scale);
  const double inertia = kgm2_to_gcm2(f.inertia_kgm2) / scale;
  out["mass_kg"] = f.mass_kg / scale;
  out["inertia_gcm2"] = inertia;
  out["com_m"] = {f.com_m[0], f.com_m[1], f.com_m[2]};
  out["com_radius_m"] = f.com_radius_m;
  out["gravity_torque_Nm"] = gravity_torque_max_Nm(f, tilt) / scale;
  std::size_t largest = 0, heaviest = 0;
  for (std::size_t k = 0; k < f.parts.size(); ++k) {
    out["parts"].push_back(part_json(f.parts[k], scale, inertia));
    if (f.parts[k].inertia_kgm2 > f.parts[largest].inertia_kgm2) largest = k;
    if (f.parts[k].mass_kg > f.parts[heaviest].mass_kg) heaviest = k;
  }
  out["largest_share_part"] = largest + 1;
  out["heaviest_part"] = heaviest + 1;
  out["over_by_gcm2"] = std::max(0.0, inertia - max_load_gcm2());
  if (scale != 1.0) {
    const Json& big = out["parts"][largest];
    out["over_text"] = fmt::format("over by {:.1f} g cm^2: the load has {:.1f} g cm^2 about the axis, the module carries "
                                   "{:.0f} g cm^2 (manual 3.5.6). Part {} ({}) holds the most, {:.1f} g cm^2 ({:.0f} %) with "
                                   "{:.3f} kg; the heaviest is part {} ({:.3f} kg).",
                                   inertia - max_load_gcm2(), inertia, max_load_gcm2(), largest + 1,
                                   big["name"].get<std::string>().empty() ? big["shape"].get<std::string>() : big["name"].get<std::string>(),
                                   big["inertia_gcm2"].get<double>(), 100 * big["share"].get<double>(), big["mass_kg"].get<double>(),
                                   heaviest + 1, out["parts"][heaviest]["mass_kg"].get<double>());
  }
  return out;
}

sizing::SizingRequest sizing_request(const Json& state) {
  sizing::SizeOptions o = size_options(state);
  o.load_gcm2 = 0.0; // replaced below by the project's load, as --load PROJECT.yaml reads it
  sizing::SizingRequest rq = sizing::make_request(o);
  const LoadFileContents load = parsed_load(state);
  rq.world.load = load.load;
  rq.world.mounting_tilt_deg = load.mounting_tilt_deg.value_or(0.0);
  rq.keep_trace = true; // as `size --report`: the plots need the trace
  rq.search_threads = io::usable_cpus(); // as `size`
  return rq;
}

SingleSizing size_single_state(const Json& state, const std::function<void()>& on_simulation) {
  SingleSizing one{sizing_request(state), {}, std::nullopt};
  one.request.on_simulation = on_simulation;
  if (normalised_state(state)["uncertainty"].get<bool>()) { // as size --uncertainty (A-SIZE-UNC-3)
    sizing::UncertainSizing us = sizing::size_with_uncertainty(one.request, default_model_card(), kUncertaintySamples,
                                                               kUncertaintySeed, io::usable_cpus());
    one.result = std::move(us.result);
    one.uncertainty = std::move(us.uncertainty);
  } else {
    one.result = sizing::size(one.request);
  }
  return one;
}

std::string answer_command(const Json& s) {
  const bool cycle = s["mode"] == "cycle";
  // The studio answers a single move without the settling spread over
  // targets a few counts apart (9 more runs, issue 35): the command says so
  // (a cycle has none).
  return size_command_line(s, "PROJECT.yaml") + (cycle ? "" : " --settling-spread-counts 0") +
         (s["uncertainty"].get<bool>() ? " --uncertainty" : "") + " --report REPORT --json";
}

Json answer(const Json& state_in, const std::function<void()>& on_simulation) {
  Json out;
  Json s;
  try {
    s = normalised_state(state_in);
    out["load"] = load_panel(s);
  } catch (const std::invalid_argument& e) {
    out["error"] = e.what();
    return out;
  }
  out["command"] = answer_command(s);
  if (out["load"]["over_by_gcm2"].get<double>() > 0) {
    out["error"] = out["load"]["over_text"];
    return out;
  }
  try {
    if (s["mode"] == "cycle") {
      add_cycle_answer(out, s, on_simulation);
      return out;
    }
    const SingleSizing one = size_single_state(s, on_simulation);
    const sizing::UncertaintyResult* u = one.uncertainty ? &*one.uncertainty : nullptr;
    Json j = sizing::to_json(one.request, one.result, {u, nullptr});
    io::round_figures(j);
    out["size"] = j;
    add_answer_parts(out, s, one.request, one.result, u);
  } catch (const std::invalid_argument& e) { // SizingInputError, ProjectError
    out["error"] = e.what();
  }
  return out;
}

std::string answer_csv(const Json& state) {
  const Json a = answer(state);
  if (a.contains("error")) throw ProjectError(a["error"].get<std::string>());
  return sizing::size_csv(a["size"]);
}

std::string answer_scenario(const Json& state) {
  if (normalised_state(state)["mode"] == "cycle") { // as `size --cycle --emit-scenario`
    const CycleSizing c = size_cycle_state(state);
    const sizing::CyclePlan plan = sizing::plan_sets(c.request);
    std::vector<int> set_of_segment;
    for (int k : plan.move_set) set_of_segment.push_back(k < 0 ? -1 : plan.sets[static_cast<std::size_t>(k)].set);
    return sizing::scenario_yaml(c.request, c.result.evaluation.sets, set_of_segment,
                                 "sized cycle " + normalised_state(state)["name"].get<std::string>());
  }
  const SingleSizing one = size_single_state(state);
  const sizing::SizingRequest& rq = one.request;
  // As `size --emit-scenario` (sizing/size_options.cpp run_size).
  return sizing::scenario_yaml(sizing::cycle_of_single(rq), {one.result.evaluation.set},
                               {rq.parameter_set, -1, rq.parameter_set, -1},
                               fmt::format("sized move {} deg back and forth", rq.angle_deg));
}

} // namespace sreh::studio
