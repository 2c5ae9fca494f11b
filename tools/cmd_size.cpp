// `sreh-twin size`: PerfectCycle-style sizing of one move back and forth
// (interfaces.md, manual 3.5.1). Evaluates the set given with --speed-dps /
// --accel-pct / --jerk-pct, or recommends the fastest feasible one.
// Exit 0 feasible, 1 infeasible, 2 bad input (a value outside the module's
// limits, an unreadable load file).
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "scenarios/scenario_parser.hpp"
#include "sizing/output.hpp"
#include "sizing/report.hpp"
#include "sizing/sizing.hpp"
#include "tools/command.hpp"

namespace sreh::tools {
namespace {

struct SizeArgs {
  double angle_deg = 0;
  std::optional<double> load_gcm2;
  std::string load_file;
  double voltage_V = 24.0;
  double dwell_s = 0.0;
  double tolerance_deg = 0.1;
  double wait_ms = 25.0;
  std::optional<double> timeout_ms;
  double ambient_C = 25.0;
  std::optional<double> speed_dps, accel_pct, jerk_pct;
  int parameter_set = 1;
  int cycles = 2;
  bool json = false;
  std::string report;
};

// A load file is YAML with a top-level `load:` key, exactly as in a scenario
// (scenarios/README.md); a scenario file works too (only its load is used).
// The scenario parser reads it, so keys, errors and MJCF paths behave the
// same: keys a scenario needs are appended at the end, which keeps every
// line number of the file.
LoadSpec load_from_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("--load {}: cannot read the file", path));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(fmt::format("{}:{}:{}: {}", path, e.mark.line + 1, e.mark.column + 1, e.msg));
  }
  if (!root.IsMap() || !root["load"]) {
    throw InputError(fmt::format("{}: expected a top-level 'load:' key (e.g. load: {{disk: {{mass_kg: 0.4, radius_m: 0.1}}}})", path));
  }
  if (!root["name"]) text += "\nname: load from " + std::filesystem::path(path).filename().string() + "\n";
  if (!root["steps"]) text += "\nsteps:\n  - comment: sizing load\n"; // a scenario needs one step
  try {
    return parse_scenario_text(text, path, std::filesystem::path(path).parent_path().string()).load;
  } catch (const ScenarioError& e) {
    throw InputError(e.what());
  }
}

sizing::SizingRequest make_request(const SizeArgs& a) {
  sizing::SizingRequest rq;
  rq.angle_deg = a.angle_deg;
  if (a.load_gcm2) rq.load = InertiaLoad{*a.load_gcm2};
  else if (!a.load_file.empty()) rq.load = load_from_file(a.load_file);
  else throw InputError("size: give the load with --load-gcm2 J or --load LOAD.yaml");
  rq.voltage_V = a.voltage_V;
  rq.dwell_s = a.dwell_s;
  rq.tolerance_deg = a.tolerance_deg;
  rq.wait_ms = a.wait_ms;
  rq.timeout_ms = a.timeout_ms;
  rq.ambient_C = a.ambient_C;
  rq.parameter_set = a.parameter_set;
  rq.cycles = a.cycles;
  if (a.speed_dps || a.accel_pct || a.jerk_pct) {
    // Options left out keep the factory value of sets 1..7 (manual 6.2).
    const sizing::MotionSetting factory;
    rq.setting = sizing::MotionSetting{a.speed_dps.value_or(factory.speed_dps), a.accel_pct.value_or(factory.accel_pct),
                                       a.jerk_pct.value_or(factory.jerk_pct)};
  }
  rq.keep_trace = !a.report.empty();
  return rq;
}

int size_command(const SizeArgs& a) {
  const sizing::SizingRequest rq = make_request(a);
  if (!a.report.empty() && !sizing::reports_available()) throw InputError("--report: this build has no renders");
  sizing::SizingResult result;
  try {
    result = sizing::size(rq);
  } catch (const sizing::SizingInputError& e) {
    throw InputError(e.what());
  }
  if (!a.report.empty()) {
    try {
      sizing::write_size_report(a.report, rq, result);
    } catch (const std::runtime_error& e) {
      throw InputError(fmt::format("--report {}: {}", a.report, e.what()));
    }
  }
  if (a.json) std::cout << sizing::to_json(rq, result).dump(2) << "\n";
  else std::cout << sizing::summary_text(rq, result);
  return result.evaluation.feasible ? 0 : 1;
}

} // namespace

SREH_REGISTER_COMMAND(30, [](CLI::App& app, int& exit_code) {
  auto a = std::make_shared<SizeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "size", "Size one move back and forth like Afag's PerfectCycle: times, torque, temperature, a recommended "
              "parameter set (exit 0 feasible, 1 infeasible, 2 bad input)");
  cmd->add_option("--angle-deg", a->angle_deg, "Move angle in degrees (the cycle is 0 -> A -> 0)")->required();
  auto* load = cmd->add_option("--load-gcm2", a->load_gcm2, "Load inertia about the axis, 0 .. 15000 g cm^2 [default: 0 unless --load]");
  auto* file = cmd->add_option("--load", a->load_file, "Load file: YAML with a 'load:' key as in a scenario");
  load->excludes(file);
  file->excludes(load);
  cmd->add_option("--voltage-V", a->voltage_V, "Motor supply 16 .. 32 V (index 85)")->capture_default_str();
  cmd->add_option("--dwell-s", a->dwell_s, "Pause after each move, s")->capture_default_str();
  cmd->add_option("--tolerance-deg", a->tolerance_deg, "Position tolerance in deg (index 64+n.5)")->capture_default_str();
  cmd->add_option("--wait-ms", a->wait_ms, "Waiting time in the window in ms (index 64+n.6)")->capture_default_str();
  cmd->add_option("--timeout-ms", a->timeout_ms, "Settling timeout in ms (index 64+n.7) [default: wait + 75 ms, >= 100 ms]");
  cmd->add_option("--ambient-C", a->ambient_C, "Ambient temperature 0 .. 50 degC")->capture_default_str();
  cmd->add_option("--speed-dps", a->speed_dps, "Evaluate this speed, 0.1 .. 4300 deg/s [default: recommend a set]");
  cmd->add_option("--accel-pct", a->accel_pct, "Evaluate this acceleration, 0.1 .. 100 % [default: recommended]");
  cmd->add_option("--jerk-pct", a->jerk_pct, "Evaluate this jerk, 0.1 .. 100 % [default: recommended]");
  cmd->add_option("--parameter-set", a->parameter_set, "Parameter set 0 .. 7 (index 64 + n)")->capture_default_str();
  cmd->add_option("--cycles", a->cycles, "Back-and-forth cycles simulated, 1 .. 20")->capture_default_str();
  cmd->add_flag("--json", a->json, "Print one JSON object on stdout");
  cmd->add_option("--report", a->report, "Write an HTML sizing report into this folder");
  cmd->callback([a, &exit_code] { exit_code = size_command(*a); });
});

} // namespace sreh::tools
