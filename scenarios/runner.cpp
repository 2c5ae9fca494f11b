#include "scenarios/runner.hpp"

#include "device_logic/device_snapshot.hpp"
#include "device_logic/fault_names.hpp"
#include "device_logic/parameter_ids.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include <fmt/format.h>

#include "scenarios/data_storage_master.hpp"
#include "scenarios/isdu_value.hpp"
#include "twin/firmware_transfer.hpp"
#include "scenarios/snapshot.hpp"

namespace sreh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// "0x8030 (Parameter value out of range)": code and IO-Link name (issue 29).
std::string hex_code(uint16_t code) { return isdu_error_label(code); }

std::string bytes_hex(const std::vector<uint8_t>& data) {
  std::string s;
  for (uint8_t b : data) s += fmt::format("{:02X}", b);
  return s.empty() ? "(none)" : s;
}

std::string seconds(double s) { return fmt::format("{:g} s", s); }

struct StopRun {}; // stop_on_failure: unwinds the step loop

std::unique_ptr<Twin> make_twin(const Scenario& s, const TwinConfig& config);

class ScenarioRun {
 public:
  ScenarioRun(const Scenario& s, const RunOptions& o) : s_(s), o_(o) {}

  RunResult run() {
    check_run_bound(s_, o_.limits); // refuse before an hour of simulation, not after
    TwinConfig config = make_twin_config(s_);
    config.record_trace = o_.record_trace;
    config.trace_sink = o_.trace_sink;
    config.move_sink = [this](const MoveRecord& m) { finished_move(m); };
    twin_ = make_twin(s_, config);
    r_.name = s_.name;
    const Snapshot first = take_snapshot(*twin_);
    r_.min_supply_V = r_.max_supply_V = first.telemetry.supply_V;
    r_.max_temperature_C = first.telemetry.temperature_C;
    try {
      for (std::size_t i = 0; i < s_.device.isdu.size(); ++i) {
        isdu_write(s_.device.isdu[i], fmt::format("device.isdu[{}]", i + 1));
      }
      data_storage_ = uses_replace(s_.steps);
      if (data_storage_) ds_backup_ = ds_upload(*twin_); // the master's first upload (manual 8)
      run_steps(s_.steps);
    } catch (const StopRun&) {
      r_.stopped_early = true;
    }
    check_run_metrics();
    finish();
    return std::move(r_);
  }

 private:
  // ---- time ----
  uint64_t cycles_for(double duration_s) const {
    // Rounded up to whole IO-Link cycles (A-SCN-3).
    return static_cast<uint64_t>(std::ceil(duration_s / twin_->master_cycle_s() - 1e-9));
  }

  void cycle() {
    // Guard for step kinds the static bound does not know (limits.cpp).
    if (twin_->time_s() >= o_.limits.max_sim_s) {
      throw ScenarioError(SourceLoc{s_.file, 0, 0}, fmt::format("simulated time reached the limit of {:g} s; raise it "
                                                                "with --max-sim-s", o_.limits.max_sim_s));
    }
    twin_->run_cycle();
    // The master serves the device's Data Storage upload request (3.2 bit 7).
    if (data_storage_ && twin_->powered() && ds_upload_requested(*twin_))
      if (auto b = ds_upload(*twin_)) ds_backup_ = std::move(b);
    const Telemetry t = twin_->telemetry();
    r_.max_temperature_C = std::max(r_.max_temperature_C, t.temperature_C);
    r_.min_supply_V = std::min(r_.min_supply_V, t.supply_V);
    r_.max_supply_V = std::max(r_.max_supply_V, t.supply_V);
    if (o_.on_cycle) o_.on_cycle(*twin_);
  }

  void cycles(uint64_t n) {
    for (uint64_t i = 0; i < n; ++i) cycle();
  }

  // ---- recording ----
  void record(const std::string& step, const SourceLoc& loc, const std::string& description, bool passed,
              const std::string& actual, const std::string& why) {
    CheckRecord check{step, loc.line, description, passed, twin_->time_s(), actual};
    ++r_.checks_recorded;
    r_.checks_held += passed ? 1 : 0;
    if (o_.check_sink) o_.check_sink(check);
    else r_.checks.push_back(std::move(check));
    if (passed) return;
    r_.passed = false;
    // The module's own view at that moment helps to see why (e.g. an error state).
    const Snapshot now = take_snapshot(*twin_);
    std::string failure = fmt::format("step {} (line {}{}): {}: {} at t={:.3f} s [{}, {:.3f} deg, error_code {}, warning_code {}]",
                                      step, loc.line, pass_, description, why, twin_->time_s(),
                                      state_name(now.state), now.position_deg, error_byte_text(now.in.error_code),
                                      warning_byte_text(now.in.warning_code));
    if (o_.failure_sink) o_.failure_sink(failure);
    else r_.failures.push_back(std::move(failure));
    if (s_.stop_on_failure) throw StopRun{};
  }

  // ---- steps ----
  void run_steps(const std::vector<Step>& steps) {
    for (const Step& step : steps) {
      if (o_.on_step) o_.on_step(step);
      std::visit([&](const auto& a) { execute(step, step.number, a); }, step.action);
    }
  }

  void execute(const Step&, const std::string&, const PdStep& a) {
    // Fields left out keep their value (interfaces.md); the step lasts one
    // cycle so that the device sees these outputs at least once.
    const ProcessDataOut before = pd_;
    apply_pd_out(a, pd_);
    twin_->set_pd_out(pd_);
    cycle();
    if ((pd_.motor_on && !before.motor_on) || (pd_.move && !before.move)) load_hint(pd_.parameter_set);
  }

  // A-SCN-30 (issue 28): the manual's first advice for tracking errors and
  // long settling is to check the parameter set, the load above all (3.5.6,
  // 7.2). The real module cannot know the attached inertia; the twin does,
  // so the run says so when a set starts that is configured far from it.
  void load_hint(uint8_t set) {
    if (set >= param::kMotionSets) return; // refused by the device (114.7.2)
    const ParamId id = param::MotionSet(set).load;
    const IsduResult res = twin_->isdu_read(id.index, id.subindex);
    if (!res.ok() || res.data.size() != wire_size(parameter_row(id).type)) return;
    const double configured = raw_to_display(id, decode_number(parameter_row(id).type, res.data));
    const double attached = std::max(0.0, twin_->load_inertia_gcm2());
    const double diff = std::abs(configured - attached);
    if (diff <= kHintRelative * attached || diff <= kHintAbsolute_gcm2) return;
    const std::string hint = fmt::format("hint: parameter set {} is configured for {:.0f} g cm^2, the attached load is {:.0f} "
                                         "g cm^2 (manual 3.5.6, 7.2)", set, configured, attached);
    if (std::find(r_.hints.begin(), r_.hints.end(), hint) == r_.hints.end()) r_.hints.push_back(hint);
  }
  static constexpr double kHintRelative = 0.2;       // A-SCN-30: more than 20 % ...
  static constexpr double kHintAbsolute_gcm2 = 100;  // ... and more than 100 g cm^2

  void execute(const Step&, const std::string&, const WaitStep& a) { cycles(cycles_for(a.duration_s)); }

  void execute(const Step& step, const std::string& id, const WaitUntilStep& a) {
    std::string description = fmt::format("wait_until {}", describe(a.until));
    if (a.after_s > 0) description += " after " + seconds(a.after_s);
    description += " within " + seconds(a.within_s);
    const uint64_t limit = cycles_for(a.within_s);
    const uint64_t earliest = cycles_for(a.after_s); // whole cycles, as every duration (A-SCN-3)
    uint64_t waited = 0;
    Evaluation e = evaluate(a.until, take_snapshot(*twin_), vars_);
    for (; waited < limit && !e.passed; ++waited) {
      cycle();
      e = evaluate(a.until, take_snapshot(*twin_), vars_);
    }
    if (e.passed && waited < earliest) { // an exact window: not before after_s
      record(id, step.loc, description, false, e.actual,
             fmt::format("held already after {}, before after_s", seconds(static_cast<double>(waited) * twin_->master_cycle_s())));
      return;
    }
    record(id, step.loc, description, e.passed, e.actual, "not reached; " + e.mismatch + busy_note());
  }

  // Still Busy at a timeout (issue 29): which set the move runs with and its
  // speed, so that a move left on set 0 (30 deg/s factory speed) is obvious.
  std::string busy_note() const {
    if (!twin_->pd_in().busy) return {};
    const std::optional<MoveRecord> move = twin_->device().pending_move();
    if (!move) return {};
    const MotionParameterSet set = twin_->device().snapshot().configuration.store.motion_set(move->parameter_set);
    return fmt::format(" (the move runs with parameter set {} at {:g} deg/s{})", move->parameter_set, set.speed_dps,
                       move->parameter_set == 0 ? "; set 0 is what a pd step without parameter_set selects" : "");
  }

  void execute(const Step& step, const std::string& id, const ExpectStep& a) {
    const Evaluation e = evaluate(a.check, take_snapshot(*twin_), vars_);
    record(id, step.loc, "expect " + e.expected, e.passed, e.actual, e.mismatch);
  }

  void execute(const Step& step, const std::string& id, const IsduReadStep& a) {
    const IsduResult res = twin_->isdu_read(a.index, a.subindex);
    if (o_.on_isdu_read) o_.on_isdu_read(a.index, a.subindex, res);
    std::string description = fmt::format("isdu_read {}.{}", a.index, a.subindex);
    if (a.expect_error) {
      description += " expect_error " + hex_code(*a.expect_error);
      const std::string actual = res.ok() ? "ok, data " + bytes_hex(res.data) : "error " + hex_code(res.error);
      record(id, step.loc, description, res.error == *a.expect_error, actual, "answered " + actual);
      return;
    }
    if (!res.ok()) {
      record(id, step.loc, description, false, "error " + hex_code(res.error), "answered error " + hex_code(res.error));
      return;
    }
    if (a.save_as && !save_isdu_number(step, id, a, res)) return;
    if (a.expect_bytes) {
      description += " expect_bytes " + pattern_hex(*a.expect_bytes);
      record(id, step.loc, description, bytes_match(*a.expect_bytes, res.data), "data " + bytes_hex(res.data),
             "read " + bytes_hex(res.data));
      return;
    }
    if (!a.expect) {
      record(id, step.loc, description, true, "data " + bytes_hex(res.data), "");
      return;
    }
    if (a.expect->text) {
      const std::string text = detail::decode_isdu_text(res.data);
      description += fmt::format(" expect \"{}\"", *a.expect->text);
      record(id, step.loc, description, text == *a.expect->text, fmt::format("\"{}\"", text),
             fmt::format("read \"{}\"", text));
      return;
    }
    description += " expect " + a.expect->number->str();
    const auto value = detail::decode_isdu_number(a.index, a.subindex, res.data);
    if (!value) {
      record(id, step.loc, description, false, "data " + bytes_hex(res.data), "not a number: data " + bytes_hex(res.data));
      return;
    }
    const double v = static_cast<double>(*value);
    std::string why;
    const bool ok = a.expect->number->holds(v, vars_, &why);
    record(id, step.loc, description, ok, std::to_string(*value),
           "read " + std::to_string(*value) + (why.empty() ? "" : " (" + why + ")"));
  }

  // save_as: the answer's number, decoded as for `expect`.
  bool save_isdu_number(const Step& step, const std::string& id, const IsduReadStep& a, const IsduResult& res) {
    const auto value = detail::decode_isdu_number(a.index, a.subindex, res.data);
    if (!value) {
      record(id, step.loc, fmt::format("isdu_read {}.{} save_as {}", a.index, a.subindex, *a.save_as), false,
             "data " + bytes_hex(res.data), "not a number to save: data " + bytes_hex(res.data));
      return false;
    }
    vars_[*a.save_as] = static_cast<double>(*value);
    return true;
  }

  static std::string pattern_hex(const std::vector<std::optional<uint8_t>>& p) {
    std::string s;
    for (const auto& b : p) s += b ? fmt::format("{:02X}", *b) : "xx";
    return s;
  }

  static bool bytes_match(const std::vector<std::optional<uint8_t>>& p, const std::vector<uint8_t>& data) {
    if (p.size() != data.size()) return false;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p[i] && *p[i] != data[i]) return false;
    }
    return true;
  }

  void execute(const Step&, const std::string& id, const IsduWriteStep& a) { isdu_write(a, id); }

  void isdu_write(const IsduWriteStep& a, const std::string& id) {
    const IsduResult res = twin_->isdu_write(a.index, a.subindex, a.data);
    const uint16_t want = a.expect_error.value_or(0);
    std::string description = fmt::format("isdu_write {}.{} = {}", a.index, a.subindex, a.value_text);
    description += a.expect_error ? " expect_error " + hex_code(*a.expect_error) : "";
    const std::string actual = res.ok() ? "ok" : "error " + hex_code(res.error);
    record(id, a.loc, description, res.error == want, actual, "answered " + actual);
  }

  void execute(const Step&, const std::string&, const TorqueStep& a) {
    twin_->set_external_torque(a.torque_Nm);
    if (!a.for_s) return; // stays until the next torque step
    cycles(cycles_for(*a.for_s));
    twin_->set_external_torque(0.0);
  }

  void execute(const Step&, const std::string&, const SupplyStep& a) { twin_->set_supply_voltage(a.voltage_V); }

  void execute(const Step& step, const std::string& id, const LoadStep& a) {
    try {
      twin_->set_load(a.load); // A-TWIN-33
    } catch (const std::invalid_argument& e) { // an MJCF load above the module's limit
      record(id, step.loc, "load", false, e.what(), e.what());
    }
  }

  void execute(const Step&, const std::string&, const LinkStep& a) {
    if (a.mode != LinkStep::Mode::Up) twin_->set_link_up(false);
    if (a.mode == LinkStep::Mode::Down) return; // stays down until `link: up`
    cycles(cycles_for(a.down_s));
    // Back up: the master's first exchange is part of the step, so the next
    // check reads the device's state now, not the frame from before the loss.
    twin_->set_link_up(true);
    cycle();
  }

  void execute(const Step&, const std::string&, const PdValidStep& a) { twin_->set_outputs_valid(a.valid); }

  // Manual 4.1: off for off_s (the world runs on) while a hand turns the
  // flange, then on; the start-up follows in the next cycles (A-LINK-3).
  void execute(const Step&, const std::string&, const PowerCycleStep& a) {
    twin_->power_off();
    twin_->turn_flange(a.turn_deg, a.off_s);
    cycles(cycles_for(a.off_s));
    twin_->power_on();
  }

  // Manual 8: a new module; with `restore` the master downloads its backup in
  // the new module's first OPERATE cycle (a refusal is a failed check).
  void execute(const Step&, const std::string& id, const ReplaceDeviceStep& a) {
    twin_->replace_device();
    if (!a.restore) return;
    for (int i = 0; i < 8 && twin_->iolink_led() != IoLinkLedMode::Operate; ++i) cycle();
    const uint16_t e = ds_backup_ ? ds_download(*twin_, *ds_backup_) : kIsduIndexNotAvailable;
    record(id, a.loc, "replace_device: the master restores its Data Storage backup", e == 0,
           e == 0 ? "restored" : fmt::format("0x{:04X}", e), ds_backup_ ? "the new module refused it" : "no backup");
  }

  static bool uses_replace(const std::vector<Step>& steps) {
    for (const Step& st : steps) {
      if (std::holds_alternative<ReplaceDeviceStep>(st.action)) return true;
      if (const auto* r = std::get_if<RepeatStep>(&st.action); r != nullptr && uses_replace(r->steps)) return true;
    }
    return false;
  }

  void execute(const Step&, const std::string&, const SetStep& a) {
    if (a.ambient_C) twin_->set_ambient_C(*a.ambient_C);
    if (a.master_cycle_s) twin_->set_master_cycle_s(*a.master_cycle_s); // checked by the parser
  }

  void execute(const Step&, const std::string&, const SaveStep& a) {
    const Snapshot now = take_snapshot(*twin_);
    for (const auto& [key, name] : a.quantity_to_name) vars_[name] = *quantity(key, now);
  }
  void execute(const Step&, const std::string&, const CommentStep&) {}

  // Manual 9 over ISDU in chunks (A-FW-4, A-FW-5): each write takes its
  // cycles; with power_off_at the supply fails once that fraction is sent
  // and returns at once (the module restarts).
  void execute(const Step&, const std::string& id, const FirmwareStep& a) {
    std::vector<uint8_t> image = Device::firmware_image(a.version, a.size_B);
    if (a.corrupt) image[image.size() / 2] ^= 0xFF;
    std::string description = fmt::format("firmware {} image {} ({} octets)", a.corrupt ? "corrupt" : "good",
                                          a.version, image.size());
    uint16_t err = 0;
    for (const IsduWriteRequest& w : firmware_requests(image)) {
      // The supply fails before the chunk that would pass F, at the latest
      // before the end command (F = 1: the image is in, but never checked).
      const bool end = w.subindex == 2 && w.data == std::vector<uint8_t>{1};
      if (a.power_off_at && w.image_octets_after > 0 &&
          (end || static_cast<double>(w.image_octets_after) > *a.power_off_at * static_cast<double>(image.size()))) {
        twin_->power_cycle(); // the supply fails with this fraction sent
        return;
      }
      cycles(isdu_write_cycles(w.data.size()));
      err = twin_->isdu_write(w.index, w.subindex, w.data).error;
      if (err != 0) break;
    }
    if (a.power_off_at) { // the transfer ended before the supply failed
      record(id, a.loc, description + fmt::format(" power_off_at {:g}", *a.power_off_at), false,
             err == 0 ? "ok" : "error " + hex_code(err), "the transfer ended before the supply failed");
      return;
    }
    const uint16_t want = a.expect_error.value_or(0);
    description += a.expect_error ? " expect_error " + hex_code(*a.expect_error) : "";
    const std::string actual = err == 0 ? "ok" : "error " + hex_code(err);
    record(id, a.loc, description, err == want, actual, "answered " + actual);
  }

  void execute(const Step&, const std::string&, const RepeatStep& a) {
    const std::string outer = pass_;
    for (int i = 0; i < a.times; ++i) {
      pass_ = fmt::format("{}, pass {}/{}", outer, i + 1, a.times);
      run_steps(a.steps);
      if (a.until && evaluate(*a.until, take_snapshot(*twin_), vars_).passed) break;
    }
    pass_ = outer;
  }

  static std::string describe(const Conditions& c) {
    // The expected side of an evaluation does not depend on the snapshot.
    return evaluate(c, Snapshot{}).expected;
  }

  // ---- whole run ----
  // Finished move records, in order, from the twin (which keeps only the
  // open or held one): kept or streamed, and summed up for the run metrics.
  void finished_move(const MoveRecord& m) {
    finished_stats_.add(m);
    ++r_.moves_recorded;
    if (o_.move_sink) o_.move_sink(m);
    else r_.moves.push_back(m);
  }

  struct MoveStats {
    uint64_t count = 0, completed = 0;
    double max_travel_s = 0, max_settling_s = 0, max_positioning_s = 0;
    void add(const MoveRecord& m) {
      ++count;
      completed += m.completed() ? 1 : 0;
      max_travel_s = std::max(max_travel_s, m.travel_s);
      // A move that never completed never settled.
      max_settling_s = std::max(max_settling_s, m.settling_s.value_or(kInf));
      max_positioning_s = std::max(max_positioning_s, m.positioning_s.value_or(kInf));
    }
  };

  void check_run_metrics() {
    MoveStats moves = finished_stats_; // and the record still open or held
    for (const MoveRecord& m : twin_->moves()) moves.add(m);
    for (const RunCheck& c : s_.expect) {
      double v = 0;
      switch (c.metric) {
        case RunMetric::MaxTrackingErrorDeg:
          v = twin_->max_tracking_error_deg(); // every control step of the run (issue 16: one maximum)
          break;
        case RunMetric::Moves: v = static_cast<double>(moves.count); break;
        case RunMetric::MovesCompleted: v = static_cast<double>(moves.completed); break;
        case RunMetric::MaxTravelS: v = moves.max_travel_s; break;
        case RunMetric::MaxSettlingS: v = moves.max_settling_s; break;
        case RunMetric::MaxPositioningS: v = moves.max_positioning_s; break;
        case RunMetric::MaxTemperatureC: v = r_.max_temperature_C; break;
        case RunMetric::MinSupplyV: v = r_.min_supply_V; break;
        case RunMetric::MaxSupplyV: v = r_.max_supply_V; break;
      }
      const std::string actual = fmt::format("{:g}", v);
      try {
        record("expect", c.loc, fmt::format("{} {}", c.key, c.range.str()), c.range.contains(v), actual,
               "was " + actual);
      } catch (const StopRun&) {
        r_.stopped_early = true;
      }
    }
  }

  void finish() {
    const Snapshot s = take_snapshot(*twin_);
    r_.final_state = FinalState{s.state, s.position_deg, s.in.error_code, s.in.warning_code, s.telemetry.led};
    for (const MoveRecord& m : twin_->moves()) finished_move(m); // the last, open or held, in run order
    r_.max_tracking_error_deg = twin_->max_tracking_error_deg();
    r_.sim_time_s = twin_->time_s();
    r_.cycles = twin_->cycles();
    if (o_.record_trace) r_.trace = twin_->trace();
    r_.nvm_image = twin_->save_nvm();
    // The run's tracking limit (index 87, one for all sets); each move's own
    // tolerance and waiting time are in its record.
    auto display = [&](ParamId id) -> double {
      const IsduResult res = twin_->isdu_read(id.index, id.subindex);
      if (!res.ok() || res.data.size() != wire_size(parameter_row(id).type)) return 0.0;
      return raw_to_display(id, decode_number(parameter_row(id).type, res.data));
    };
    r_.tracking_limit_deg = display(param::kTrackingErrorActive) != 0 ? display(param::kTrackingErrorMax) : 0.0;
  }

  const Scenario& s_;
  const RunOptions& o_;
  std::unique_ptr<Twin> twin_;
  bool data_storage_ = false;          // the scenario replaces the device: the master keeps a backup
  std::optional<DsBackup> ds_backup_;
  ProcessDataOut pd_{}; // the PLC's outputs; kept across power cycles like a real PLC's
  RunResult r_;
  MoveStats finished_stats_; // of the records handed over by the twin
  std::string pass_; // ", pass 2/5" inside a repeat
  Variables vars_;   // save_as / save, by name
};

// The scenario's twin; a setup the twin rejects (e.g. an invalid MJCF load)
// is the scenario's error, at its load line.
std::unique_ptr<Twin> make_twin(const Scenario& s, const TwinConfig& config) {
  try {
    return std::make_unique<Twin>(config);
  } catch (const std::invalid_argument& e) {
    // One line on stderr (interfaces.md): MuJoCo's messages span several.
    std::string why = e.what();
    std::replace(why.begin(), why.end(), '\n', ' ');
    const bool has_load = !std::holds_alternative<NoLoad>(s.world.load);
    throw ScenarioError(has_load ? s.world.load_loc : SourceLoc{s.file, 0, 0},
                        fmt::format("{}the twin rejects this setup: {}", has_load ? "load: " : "", why));
  }
}

std::vector<uint8_t> read_bytes(const std::string& path, const SourceLoc& loc) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(loc, fmt::format("device.nvm_image: cannot read '{}'", path));
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace

TwinConfig make_twin_config(const Scenario& s) {
  TwinConfig c = twin_config(s.world);
  c.cycle_s = s.sim.cycle_s;
  if (s.device.nvm_image_path) c.nvm_image = read_bytes(*s.device.nvm_image_path, s.device.nvm_image_loc);
  c.record_trace = false;
  return c;
}

void check_setup(const Scenario& scenario, const Limits& limits) {
  check_run_bound(scenario, limits);
  make_twin(scenario, make_twin_config(scenario));
}

RunResult run_scenario(const Scenario& scenario, const RunOptions& options) {
  return ScenarioRun(scenario, options).run();
}

} // namespace sreh
