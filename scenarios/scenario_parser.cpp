// Scenario YAML -> plain structs. Every key is documented in
// scenarios/README.md; every limit that the manual does not give is in
// docs/assumptions/scenarios.md (A-SCN-*).
#include "scenarios/scenario_parser.hpp"

#include "io/text.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <set>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "device_logic/units.hpp"
#include "scenarios/comparison_parser.hpp"
#include "scenarios/conformance_steps.hpp"
#include "scenarios/isdu_value.hpp"
#include "scenarios/snapshot.hpp"
#include "twin/model_card.hpp"
#include "scenarios/yaml_reader.hpp"
#include "scenarios/yaml_safety.hpp"
#include "scenarios/world_parser.hpp"

namespace sreh {
namespace {

namespace fs = std::filesystem;
using detail::YamlReader;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Half a wire count (manual 2.5): a plain position in degrees matches the nearest count.
constexpr double kHalfWireCountDeg = 180.0 / static_cast<double>(kWireCountsPerRev);
// A-SCN-1: plausibility limits of world inputs.
constexpr WorldRanges kSupplyRange{}; // a `supply:` step: the world's supply range
constexpr double kMaxTorqueNm = 50.0;
constexpr double kMaxDurationS = 3600.0;
constexpr int kMaxRepeat = 100000;

const std::vector<std::string_view> kConditionKeys = {
    "state", "position_deg", "position_raw", "error_code", "warning_code", "error", "warning",
    "led", "iolink_led", "temperature_C", "supply_V", "velocity_dps", "tracking_error_deg"};

const std::vector<std::string_view> kStepKinds = {
    "pd", "wait_s", "wait_until", "expect", "isdu_read", "isdu_write", "torque", "supply",
    "link", "pd_valid", "power", "comment", "firmware", "repeat", "set", "save", "load", "replace_device"};

std::optional<State> state_from_name(const std::string& s) {
  for (State st : {State::MotorOff, State::Ready, State::Busy, State::Done, State::ErrorOn, State::ErrorOff}) {
    if (state_name(st) == s) return st;
  }
  return std::nullopt;
}

std::optional<LedColor> led_from_name(const std::string& s) {
  for (LedColor c : {LedColor::Off, LedColor::Green, LedColor::Yellow, LedColor::Blue, LedColor::Red, LedColor::Orange,
                     LedColor::White, LedColor::Violet}) {
    if (led_name(c) == s) return c;
  }
  return std::nullopt;
}

std::optional<IoLinkLedMode> iolink_led_from_name(const std::string& s) {
  for (IoLinkLedMode m : {IoLinkLedMode::NotConnected, IoLinkLedMode::Startup, IoLinkLedMode::Preoperate,
                          IoLinkLedMode::Operate}) {
    if (iolink_led_name(m) == s) return m;
  }
  return std::nullopt;
}

class Parser {
 public:
  Parser(const std::string& file, std::string base_dir) : r_(file), base_dir_(std::move(base_dir)) {}

  Scenario parse(const YAML::Node& root) {
    std::vector<std::string_view> keys = {"name", "description"};
    keys.insert(keys.end(), detail::kWorldTopKeys.begin(), detail::kWorldTopKeys.end());
    keys.insert(keys.end(), {"sim", "stop_on_failure", "steps", "expect"});
    r_.check_map(root, "scenario", keys);
    Scenario s;
    s.file = r_.file();
    s.name = r_.text(r_.require(root, "name", "scenario"), "name");
    s.world = world_.read(root, WorldRanges{}, {"nvm_image", "isdu"});
    if (root["device"]) parse_device(root["device"], s.device);
    if (root["sim"]) parse_sim(root["sim"], s);
    check_clocks(s, root["sim"] ? root["sim"] : root);
    physics_dt_s_ = s.world.physics_dt_s;
    if (root["stop_on_failure"]) s.stop_on_failure = r_.boolean(root["stop_on_failure"], "stop_on_failure");
    const YAML::Node steps = r_.require(root, "steps", "scenario");
    s.steps = parse_steps(steps, "", "steps");
    if (root["expect"]) s.expect = parse_run_expect(root["expect"]);
    return s;
  }

 private:
  // ---- world and configuration ----
  // The device's own keys; its world keys (supply, ambient) are the world reader's.
  void parse_device(const YAML::Node& n, DeviceSetup& d) {
    if (n["nvm_image"]) {
      d.nvm_image_loc = r_.loc(n["nvm_image"]);
      d.nvm_image_path = world_.existing_file(n["nvm_image"], "device.nvm_image", false);
    }
    if (n["isdu"]) {
      const YAML::Node list = n["isdu"];
      if (!list.IsSequence()) r_.fail(list, "device.isdu: expected a list of {index, subindex, value}");
      for (std::size_t i = 0; i < list.size(); ++i) {
        d.isdu.push_back(parse_isdu_write(list[i], fmt::format("device.isdu[{}]", i)));
      }
    }
  }

  // `sim:`: the IO-Link cycle, and the world's physics step and thermal time scale.
  void parse_sim(const YAML::Node& n, Scenario& sc) {
    r_.check_map(n, "sim", {"physics_dt_s", "cycle_s", "thermal_time_scale"});
    double& physics_dt_s = sc.world.physics_dt_s;
    double& cycle_s = sc.sim.cycle_s;
    if (n["physics_dt_s"]) physics_dt_s = r_.number(n["physics_dt_s"], "sim.physics_dt_s", 1e-6, 1e-3);
    // manual 1: minimum IO-Link cycle time 2 ms.
    if (n["cycle_s"]) cycle_s = r_.number(n["cycle_s"], "sim.cycle_s", detail::kMinCycleS, detail::kMaxCycleS);
    if (!detail::integer_multiple(cycle_s, physics_dt_s)) {
      r_.fail(n["cycle_s"] ? n["cycle_s"] : n["physics_dt_s"],
              fmt::format("sim: cycle_s {} must be an integer multiple of physics_dt_s {}", cycle_s, physics_dt_s));
    }
    if (n["thermal_time_scale"]) {
      sc.world.thermal.time_scale = r_.number(n["thermal_time_scale"], "sim.thermal_time_scale", 1.0, 1e6);
    }
  }

  // Issue 25: the physics sub-steps the drive's control period (model card).
  void check_clocks(const Scenario& s, const YAML::Node& at) {
    const double period_s = s.world.module.drive.control_period_s();
    if (!detail::integer_multiple(period_s, s.world.physics_dt_s)) {
      r_.fail(at["physics_dt_s"] ? at["physics_dt_s"] : at,
              fmt::format("sim.physics_dt_s {} must divide the drive's control period {} s (model card "
                          "control_period): the physics sub-steps the drive's clock",
                          s.world.physics_dt_s, period_s));
    }
    if (!detail::integer_multiple(s.sim.cycle_s, period_s)) {
      r_.fail(at["cycle_s"] ? at["cycle_s"] : at,
              fmt::format("sim.cycle_s {} must be an integer multiple of the drive's control period {} s",
                          s.sim.cycle_s, period_s));
    }
  }

  // ---- steps ----
  std::vector<Step> parse_steps(const YAML::Node& n, const std::string& prefix, std::string_view what) {
    if (!n.IsSequence()) r_.fail(n, fmt::format("{}: expected a list of steps", what));
    if (n.size() == 0) r_.fail(n, fmt::format("{}: no steps", what));
    std::vector<Step> steps;
    for (std::size_t i = 0; i < n.size(); ++i) {
      steps.push_back(parse_step(n[i], prefix + std::to_string(i + 1)));
    }
    return steps;
  }

  Step parse_step(const YAML::Node& n, const std::string& number) {
    const std::string what = "step " + number;
    std::vector<std::string_view> allowed = kStepKinds;
    r_.check_map(n, what, allowed);
    Step step;
    step.number = number;
    step.loc = r_.loc(n);
    int actions = 0;
    YAML::Node v;
    for (const auto& kv : n) {
      const std::string key = kv.first.Scalar();
      if (key == "comment" && n.size() > 1) continue; // a remark next to an action
      ++actions;
      step.kind = key;
      v = kv.second;
    }
    if (actions != 1) r_.fail(n, fmt::format("{}: one action per step (got {})", what, actions));
    if (step.kind != "comment" && n["comment"]) step.comment = r_.text(n["comment"], what + ".comment");
    const std::string kw = what + ": " + step.kind;
    const std::string& k = step.kind;
    if (k == "pd") step.action = parse_pd(v, kw);
    else if (k == "wait_s") step.action = WaitStep{r_.number(v, kw, 0.0, kMaxDurationS)};
    else if (k == "set") step.action = detail::parse_set(r_, v, kw, physics_dt_s_);
    else if (k == "save") step.action = detail::parse_save(r_, v, kw, saved_);
    else if (k == "wait_until") step.action = parse_wait_until(v, kw);
    else if (k == "expect") {
      r_.check_map(v, kw, kConditionKeys);
      ExpectStep e{parse_conditions(v, kw)};
      if (e.check.empty()) r_.fail(v, kw + ": nothing to check");
      step.action = e;
    } else if (k == "isdu_read") step.action = parse_isdu_read(v, kw);
    else if (k == "isdu_write") step.action = parse_isdu_write(v, kw);
    else if (k == "torque") {
      r_.check_map(v, kw, {"Nm", "for_s"});
      TorqueStep t{r_.number(r_.require(v, "Nm", kw), kw + ".Nm", -kMaxTorqueNm, kMaxTorqueNm), std::nullopt};
      if (v["for_s"]) t.for_s = r_.number(v["for_s"], kw + ".for_s", 0.0, kMaxDurationS);
      step.action = t;
    } else if (k == "supply") {
      r_.check_map(v, kw, {"V"});
      step.action = SupplyStep{r_.number(r_.require(v, "V", kw), kw + ".V", kSupplyRange.min_supply_V, kSupplyRange.max_supply_V)};
    } else if (k == "load") {
      step.action = LoadStep{world_.load(v)};
    } else if (k == "link") {
      step.action = detail::parse_link(r_, v, kw);
    } else if (k == "pd_valid") step.action = PdValidStep{r_.boolean(v, kw)};
    else if (k == "power") step.action = detail::parse_power(r_, v, kw); else if (k == "comment") step.action = CommentStep{r_.text(v, kw)};
    else if (k == "replace_device") {
      const std::string how = r_.text(v, kw);
      if (how != "restore" && how != "none")
        r_.fail(v, fmt::format("{}: expected restore (the master's Data Storage backup) or none, got '{}'", kw, how));
      step.action = ReplaceDeviceStep{how == "restore", step.loc};
    } else if (k == "firmware") {
      FirmwareStep f = detail::parse_firmware(r_, v, kw);
      f.loc = step.loc;
      step.action = f;
    }
    else { // repeat
      r_.check_map(v, kw, {"times", "until", "steps"});
      RepeatStep rep;
      rep.times = static_cast<int>(r_.integer(r_.require(v, "times", kw), kw + ".times", 1, kMaxRepeat));
      if (const YAML::Node u = v["until"]) {
        r_.check_map(u, kw + ".until", kConditionKeys);
        rep.until = parse_conditions(u, kw + ".until");
        if (rep.until->empty()) r_.fail(u, kw + ".until: no condition");
      }
      rep.steps = parse_steps(r_.require(v, "steps", kw), number + ".", kw + ".steps");
      step.action = std::move(rep);
    }
    return step;
  }

  PdStep parse_pd(const YAML::Node& n, const std::string& what) {
    r_.check_map(n, what, pd_out_keys());
    // Fields, types and ranges: the process-data table (scenarios/pd_out_fields.hpp).
    return read_pd_out(detail::YamlFieldSource(r_, n, what), what);
  }

  WaitUntilStep parse_wait_until(const YAML::Node& n, const std::string& what) {
    std::vector<std::string_view> keys = kConditionKeys;
    keys.push_back("within_s");
    keys.push_back("after_s");
    r_.check_map(n, what, keys);
    WaitUntilStep w;
    w.within_s = r_.number(r_.require(n, "within_s", what), what + ".within_s", 0.0, kMaxDurationS);
    if (n["after_s"]) {
      w.after_s = r_.number(n["after_s"], what + ".after_s", 0.0, kMaxDurationS);
      if (w.after_s > w.within_s) {
        r_.fail(n["after_s"], fmt::format("{}.after_s: {} is later than within_s {}", what, w.after_s, w.within_s));
      }
    }
    w.until = parse_conditions(n, what);
    if (w.until.empty()) r_.fail(n, what + ": no condition to wait for");
    return w;
  }

  Conditions parse_conditions(const YAML::Node& n, const std::string& what) {
    Conditions c;
    auto names = [&](const char* key, auto from_name, auto& out, const char* known) {
      const YAML::Node v = n[key];
      if (!v) return;
      const std::string kw = fmt::format("{}.{}", what, key);
      auto one = [&](const YAML::Node& x) {
        const auto parsed = from_name(r_.text(x, kw));
        if (!parsed) {
          // Issue 39: "did you mean" ("ready" -> "Ready").
          std::vector<std::string> choices;
          for (std::string_view rest = known; !rest.empty();) {
            const std::size_t comma = rest.find(", ");
            choices.emplace_back(rest.substr(0, comma));
            rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 2);
          }
          const std::string guess = io::closest_name(x.Scalar(), choices);
          r_.fail(x, guess.empty() ? fmt::format("{}: unknown '{}' (known: {})", kw, x.Scalar(), known)
                                   : fmt::format("{}: unknown '{}'; did you mean '{}'? (known: {})", kw, x.Scalar(), guess, known));
        }
        out.push_back(*parsed);
      };
      if (v.IsSequence()) {
        if (v.size() == 0) r_.fail(v, kw + ": empty list");
        for (const auto& x : v) one(x);
      } else {
        one(v);
      }
    };
    names("state", state_from_name, c.state, "MotorOff, Ready, Busy, Done, ErrorOn, ErrorOff");
    names("led", led_from_name, c.led, "off, green, yellow, blue, red, orange, white, violet");
    names("iolink_led", iolink_led_from_name, c.iolink_led, "off, startup, preoperate, operate");
    auto num = [&](const char* key, std::optional<Comparison>& out, double min, double max, bool ints, double tol) {
      if (n[key]) out = detail::read_comparison(r_, n[key], fmt::format("{}.{}", what, key), {min, max, ints, tol}, saved_);
    };
    if (n["position_deg"] && n["position_raw"]) r_.fail(n["position_raw"], what + ": give position_deg or position_raw, not both");
    num("position_deg", c.position_deg, -kWireLimitDeg, kWireLimitDeg, false, kHalfWireCountDeg);
    num("position_raw", c.position_raw, std::numeric_limits<int32_t>::min(), std::numeric_limits<int32_t>::max(), true, 0);
    num("error_code", c.error_code, 0, 255, true, 0);
    num("warning_code", c.warning_code, 0, 255, true, 0);
    num("temperature_C", c.temperature_C, -100, 300, false, 0);
    num("supply_V", c.supply_V, 0, 100, false, 0);
    num("velocity_dps", c.velocity_dps, -1e6, 1e6, false, 0);
    num("tracking_error_deg", c.tracking_error_deg, -1e6, 1e6, false, 0);
    if (n["error"]) c.error = r_.boolean(n["error"], what + ".error");
    if (n["warning"]) c.warning = r_.boolean(n["warning"], what + ".warning");
    return c;
  }

  uint16_t isdu_error_code(const YAML::Node& n, const std::string& what) {
    // ISDU error codes are 0x8000..0x80FF (iolink.md); 0 would mean success.
    return static_cast<uint16_t>(r_.integer(n, what, 0x8000, 0x80FF));
  }

  IsduReadStep parse_isdu_read(const YAML::Node& n, const std::string& what) {
    r_.check_map(n, what, {"index", "subindex", "expect", "expect_error", "expect_bytes", "save_as"});
    IsduReadStep s;
    s.index = static_cast<uint16_t>(r_.integer(r_.require(n, "index", what), what + ".index", 0, 0xFFFF));
    if (n["subindex"]) s.subindex = static_cast<uint8_t>(r_.integer(n["subindex"], what + ".subindex", 0, 0xFF));
    const int given = (n["expect"] ? 1 : 0) + (n["expect_error"] ? 1 : 0) + (n["expect_bytes"] ? 1 : 0);
    if (given > 1) {
      r_.fail(n["expect_error"] ? n["expect_error"] : n["expect_bytes"],
              what + ": give one of expect, expect_bytes, expect_error");
    }
    if (n["save_as"] && n["expect_error"]) r_.fail(n["save_as"], what + ": save_as needs an answer, not expect_error");
    if (n["save_as"] && detail::is_text_parameter(s.index, s.subindex)) {
      r_.fail(n["save_as"], fmt::format("{}.save_as: index {}.{} is a text, only numbers can be saved", what, s.index, s.subindex));
    }
    if (n["expect_bytes"]) s.expect_bytes = detail::parse_hex_pattern(r_, n["expect_bytes"], what + ".expect_bytes");
    if (n["expect_error"]) s.expect_error = isdu_error_code(n["expect_error"], what + ".expect_error");
    if (const YAML::Node e = n["expect"]) {
      IsduValueCheck check;
      if (detail::is_text_parameter(s.index, s.subindex) || (e.IsScalar() && r_.is_quoted(e))) {
        check.text = r_.text(e, what + ".expect");
      } else {
        check.number = detail::read_comparison(r_, e, what + ".expect", {-4294967296.0, 4294967295.0, true, 0}, saved_);
      }
      s.expect = check;
    }
    if (n["save_as"]) { // after expect: a check may compare with the value saved before
      s.save_as = detail::read_variable_name(r_, n["save_as"], what + ".save_as");
      saved_.insert(*s.save_as);
    }
    return s;
  }

  IsduWriteStep parse_isdu_write(const YAML::Node& n, const std::string& what) {
    r_.check_map(n, what, {"index", "subindex", "value", "bytes", "expect_error"});
    IsduWriteStep s;
    s.loc = r_.loc(n);
    s.index = static_cast<uint16_t>(r_.integer(r_.require(n, "index", what), what + ".index", 0, 0xFFFF));
    if (n["subindex"]) s.subindex = static_cast<uint8_t>(r_.integer(n["subindex"], what + ".subindex", 0, 0xFF));
    if (n["value"] && n["bytes"]) r_.fail(n["bytes"], what + ": give value or bytes, not both");
    if (n["value"]) {
      s.data = detail::encode_isdu_value(r_, n["value"], s.index, s.subindex, what + ".value");
      s.value_text = YAML::Dump(n["value"]);
    } else if (const YAML::Node b = n["bytes"]) {
      // Raw octets: for length errors (0x8033 / 0x8034) and octet strings.
      if (!b.IsSequence()) r_.fail(b, what + ".bytes: expected a list of octets");
      for (const auto& x : b) s.data.push_back(static_cast<uint8_t>(r_.integer(x, what + ".bytes", 0, 255)));
      s.value_text = YAML::Dump(b);
    } else {
      r_.fail(n, what + ": missing required key 'value' (or 'bytes')");
    }
    if (n["expect_error"]) s.expect_error = isdu_error_code(n["expect_error"], what + ".expect_error");
    return s;
  }

  // ---- whole-run checks ----
  std::vector<RunCheck> parse_run_expect(const YAML::Node& n) {
    struct Key { std::string_view name; RunMetric metric; char plain; }; // plain: '<' at most, '>' at least, '=' exactly
    static const Key keys[] = {
        {"max_tracking_error_deg", RunMetric::MaxTrackingErrorDeg, '<'},
        {"moves", RunMetric::Moves, '='},
        {"moves_completed", RunMetric::MovesCompleted, '='},
        {"max_travel_s", RunMetric::MaxTravelS, '<'},
        {"max_settling_s", RunMetric::MaxSettlingS, '<'},
        {"max_positioning_s", RunMetric::MaxPositioningS, '<'},
        {"max_temperature_C", RunMetric::MaxTemperatureC, '<'},
        {"min_supply_V", RunMetric::MinSupplyV, '>'},
        {"max_supply_V", RunMetric::MaxSupplyV, '<'},
    };
    std::vector<std::string_view> allowed;
    for (const auto& k : keys) allowed.push_back(k.name);
    r_.check_map(n, "expect", allowed);
    std::vector<RunCheck> checks;
    for (const auto& kv : n) {
      const std::string name = kv.first.Scalar();
      for (const auto& k : keys) {
        if (k.name != name) continue;
        const std::string what = "expect." + name;
        const bool counts = k.plain == '=';
        Range r = r_.range(kv.second, what, counts ? 0 : -1e6, counts ? 1e6 : 1e6, counts, 0);
        if (r.exact && k.plain == '<') r = Range{-kInfinity, r.max, false};
        if (r.exact && k.plain == '>') r = Range{r.min, kInfinity, false};
        checks.push_back(RunCheck{k.metric, name, r, r_.loc(kv.second)});
      }
    }
    return checks;
  }

  YamlReader r_;
  std::string base_dir_;
  detail::WorldReader world_{r_, base_dir_};
  double physics_dt_s_ = 0;     // for checks of later steps (set.master_cycle_s)
  std::set<std::string> saved_; // names saved so far, in file order
};

} // namespace

Scenario parse_scenario_text(const std::string& yaml_text, const std::string& file, const std::string& base_dir,
                             const Limits& limits) {
  const YAML::Node root = detail::load_yaml_safely(yaml_text, file, limits);
  if (!root.IsDefined() || root.IsNull()) throw ScenarioError(SourceLoc{file, 1, 1}, "empty scenario (expected name, steps, ...)");
  try {
    return Parser(file, base_dir).parse(root);
  } catch (const YAML::Exception& e) { // a yaml-cpp conversion the checks above did not foresee
    SourceLoc loc{file, e.mark.is_null() ? 0 : e.mark.line + 1, e.mark.is_null() ? 0 : e.mark.column + 1};
    throw ScenarioError(loc, e.msg);
  }
}

void apply_command_line_model(Scenario& s, const std::string& model_path) {
  if (model_path.empty()) return;
  try {
    ModelCard card = default_model_card();
    if (!s.world.model_file.empty()) card = apply_model_file(card, s.world.model_file);
    s.world.module = apply_model_file(card, model_path).module_model();
  } catch (const ModelCardError& e) {
    throw ScenarioError(SourceLoc{s.file}, std::string("--model: ") + e.what());
  }
  const double period_s = s.world.module.drive.control_period_s();
  if (!detail::integer_multiple(period_s, s.world.physics_dt_s) || !detail::integer_multiple(s.sim.cycle_s, period_s)) {
    throw ScenarioError(SourceLoc{s.file}, fmt::format("sim: physics_dt_s {} and cycle_s {} do not fit the control period "
                                                       "{} s of --model {}", s.world.physics_dt_s, s.sim.cycle_s, period_s,
                                                       model_path));
  }
}

Scenario parse_scenario_file(const std::string& path, const Limits& limits) {
  const std::string text = detail::read_limited_file(path, limits, "scenario file");
  const fs::path parent = fs::path(path).parent_path();
  return parse_scenario_text(text, path, parent.string(), limits);
}

} // namespace sreh
