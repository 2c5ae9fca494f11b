// The studio's answer to a cycle (issue 37, docs/studio.md "Cycles"): the
// cycle file of the state sized as `sreh-twin size --cycle` sizes it
// (parse_cycle_text, size_cycle, cycle_to_json), with the verdict block,
// the plots, the writes of every set when the cycle is feasible, and how
// far over each limit it is when not.
#pragma once
#include <functional>
#include <optional>
#include <string>

#include "sizing/cycle.hpp"
#include "sizing/uncertainty.hpp"
#include "studio/project.hpp"

namespace sreh::studio {

// The uncertainty switch: `size --uncertainty`'s samples and seed.
inline constexpr int kUncertaintySamples = 32;
inline constexpr uint64_t kUncertaintySeed = 1;

// The cycle request of a cycle state, as `size --cycle PROJECT.yaml --report` reads it.
sizing::CycleRequest cycle_request(const Json& state);

struct CycleSizing {
  sizing::CycleRequest request;
  sizing::CycleResult result;
  std::optional<sizing::UncertaintyResult> uncertainty; // with the switch on
};
// Sizes the cycle (and its samples with the switch on); `on_simulation`
// is called as each simulation starts.
CycleSizing size_cycle_state(const Json& state, const std::function<void()>& on_simulation = {});

// Adds "size" (the size --cycle --json object), "verdict_html",
// "plots_html", "summary", "writes", "writes_ready", "uncertainty_html"
// and, infeasible, "way_out" to `out`.
void add_cycle_answer(Json& out, const Json& state, const std::function<void()>& on_simulation);

} // namespace sreh::studio
