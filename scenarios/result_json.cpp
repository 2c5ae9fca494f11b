#include "scenarios/result_json.hpp"

#include <cmath>

#include "io/figures.hpp"

namespace sreh {
namespace {

// JSON has no infinity / NaN: such values become null.
nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }
// Simulated times are whole cycles; rounding hides float noise (0.10400000000000001).
nlohmann::json time_s(double v) { return number(std::round(v * 1e9) / 1e9); }

nlohmann::json optional_time(const std::optional<double>& v) { return v ? time_s(*v) : nlohmann::json(nullptr); }

// Figures at their unit's resolution (issue 29), in the streamed and the
// in-memory answer alike.
nlohmann::json rounded(nlohmann::json j) {
  io::round_figures(j);
  return j;
}

} // namespace

// The device's move record as `run --json` shows it (interfaces.md `moves[]`).
nlohmann::json move_json(const MoveRecord& m) {
  return rounded({{"number", m.number},
          {"parameter_set", m.parameter_set},
          {"start_s", time_s(m.start_s)},
          {"start_deg", number(m.start_deg)},
          {"target_deg", number(m.target_deg)},
          {"end_deg", number(m.end_deg)},
          {"tolerance_deg", number(m.tolerance_deg)},
          {"wait_ms", number(m.wait_ms)},
          {"settling_timeout_ms", number(m.settling_timeout_ms)},
          {"settling_timeout_active", m.settling_timeout_active},
          {"travel_s", time_s(m.travel_s)},
          {"settling_s", optional_time(m.settling_s)},
          {"positioning_s", optional_time(m.positioning_s)},
          {"in_window_s", optional_time(m.in_window_s)},
          {"max_tracking_error_deg", number(m.max_tracking_error_deg)},
          {"overshoot_deg", number(m.overshoot_deg)},
          {"stopped", m.stopped},
          {"outcome", outcome_name(m.outcome)},
          {"error_code", m.error_code},
          {"completed", m.completed()}});
}

nlohmann::json check_json(const CheckRecord& c) {
  return rounded({{"step", c.step},
          {"line", c.line},
          {"description", c.description},
          {"passed", c.passed},
          {"t_s", time_s(c.t_s)},
          {"actual", c.actual}});
}

nlohmann::json to_json(const RunResult& r) {
  nlohmann::json moves = nlohmann::json::array();
  for (const MoveRecord& m : r.moves) {
    moves.push_back(move_json(m));
  }
  nlohmann::json checks = nlohmann::json::array();
  for (const CheckRecord& c : r.checks) {
    checks.push_back(check_json(c));
  }
  return rounded({
      {"name", r.name},
      {"passed", r.passed},
      {"failures", r.failures},
      {"hints", r.hints},
      {"stopped_early", r.stopped_early},
      {"moves", moves},
      {"final",
       {{"state", std::string(state_name(r.final_state.state))},
        {"position_deg", number(r.final_state.position_deg)},
        {"error_code", r.final_state.error_code},
        {"warning_code", r.final_state.warning_code},
        {"led", std::string(led_name(r.final_state.led))}}},
      {"checks", checks},
      {"sim_time_s", time_s(r.sim_time_s)},
      {"cycles", r.cycles},
      {"max_tracking_error_deg", number(r.max_tracking_error_deg)},
      {"max_temperature_C", number(r.max_temperature_C)},
      {"min_supply_V", number(r.min_supply_V)},
      {"max_supply_V", number(r.max_supply_V)},
  });
}

} // namespace sreh
