// A scenario: a PLC program plus the world it runs in (interfaces.md
// "Scenario files"), as plain structs. YAML stays in scenario_parser.cpp;
// the runner only sees these values. Every element keeps where it came from
// (file:line:col) so that failures can cite the scenario line.
#pragma once
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "device_logic/device_types.hpp"
#include "scenarios/comparison.hpp"
#include "scenarios/pd_out_fields.hpp"
#include "scenarios/source_loc.hpp"
#include "scenarios/world.hpp"
#include "twin/twin.hpp"

namespace sreh {

// What a PLC (process data in) or the world (LED band, sensors) shows at an
// instant. Every present field must hold; `state` and `led` hold when the
// value is any of the listed ones.
struct Conditions {
  std::vector<State> state;
  std::optional<Comparison> position_deg;       // process data in, manual 2.5
  std::optional<Comparison> position_raw;       // wire counts, 2^16 per revolution
  std::optional<Comparison> error_code;         // bit field, manual 2.4
  std::optional<Comparison> warning_code;
  std::optional<bool> error;                    // summary bits, manual 2.3
  std::optional<bool> warning;
  std::vector<LedColor> led;                    // LED band, manual 3.1 / index 83
  std::vector<IoLinkLedMode> iolink_led;        // IO-Link status LED, manual 1
  std::optional<Comparison> temperature_C;      // world side (twin telemetry)
  std::optional<Comparison> supply_V;           // world side: motor voltage at the module
  std::optional<Comparison> velocity_dps;       // world side
  std::optional<Comparison> tracking_error_deg; // world side
  bool empty() const;
};

// Process data out fields (manual 2.2); fields left out keep their value.
// Process data out fields to set (scenarios/pd_out_fields.hpp; left out: kept).
using PdStep = PdOutUpdate;

struct WaitStep { double duration_s = 0; };
// `after_s`: the conditions must not hold before it (an exact time window).
struct WaitUntilStep { Conditions until; double within_s = 0; double after_s = 0; };
struct ExpectStep { Conditions check; };

// Expected value of an ISDU read: a number / range (raw wire value decoded
// with the parameter table's type) or a string.
struct IsduValueCheck {
  std::optional<Comparison> number;
  std::optional<std::string> text;
};

struct IsduReadStep {
  uint16_t index = 0;
  uint8_t subindex = 0;
  std::optional<IsduValueCheck> expect;
  std::optional<uint16_t> expect_error; // the ISDU error code the device must answer
  // expect_bytes: the whole answer octet by octet; nullopt = "xx", not checked.
  std::optional<std::vector<std::optional<uint8_t>>> expect_bytes;
  std::optional<std::string> save_as;   // remember the decoded number as $NAME
};

struct IsduWriteStep {
  uint16_t index = 0;
  uint8_t subindex = 0;
  std::vector<uint8_t> data;            // encoded with the parameter table's type
  std::string value_text;               // as written in the scenario, for messages
  std::optional<uint16_t> expect_error; // absent: the write must succeed
  SourceLoc loc;
};

struct TorqueStep { double torque_Nm = 0; std::optional<double> for_s; }; // no for_s: stays on
struct SupplyStep { double voltage_V = 24; };
// `load:` another load on the flange from now on (a gripper picks or
// releases a part, A-TWIN-33); the device's 64+n.4 is not changed.
struct LoadStep { LoadSpec load = NoLoad{}; };
// `link: {down_s}` = down, wait, up; `link: down` / `link: up` alone. Going
// up takes one cycle: the master's first exchange (scenarios/README.md Timing).
struct LinkStep {
  enum class Mode { DownFor, Down, Up };
  Mode mode = Mode::DownFor;
  double down_s = 0;
};
struct PdValidStep { bool valid = true; };
// `power: cycle` (off_s 0) or `power: {off_s, turn_deg}` (manual 4.1).
struct PowerCycleStep { double off_s = 0; double turn_deg = 0; };
// `replace_device: restore | none` (manual 8): a factory-new module in this
// one's place; `restore`: the master downloads its Data Storage backup once
// the new module is up (the runner keeps that backup as a master does:
// uploaded at the start and whenever the device asks).
struct ReplaceDeviceStep { bool restore = true; SourceLoc loc; };
// `set:`: rig settings that change mid-run.
struct SetStep {
  std::optional<double> ambient_C;
  std::optional<double> master_cycle_s;
};
// `save:`: remember a condition quantity (position_deg, ...) as $NAME.
struct SaveStep { std::vector<std::pair<std::string, std::string>> quantity_to_name; };
struct CommentStep { std::string text; };
// Manual 9: transfer a firmware image in boot mode; `corrupt` spoils its checksum.
struct FirmwareStep {
  bool corrupt = false;
  std::string version = "1.1.0";
  std::size_t size_B = 0;               // 0: the smallest image for `version`
  std::optional<double> power_off_at;   // the supply fails when this fraction is transferred
  std::optional<uint16_t> expect_error; // absent: the update must succeed
  SourceLoc loc;
};

struct Step;
struct RepeatStep {
  int times = 1;                  // at most this many passes
  std::optional<Conditions> until; // checked after each pass: holds -> stop repeating (not a check)
  std::vector<Step> steps;
};

using StepAction = std::variant<PdStep, WaitStep, WaitUntilStep, ExpectStep, IsduReadStep, IsduWriteStep,
                                TorqueStep, SupplyStep, LinkStep, PdValidStep, PowerCycleStep, CommentStep,
                                FirmwareStep, RepeatStep, SetStep, SaveStep, LoadStep, ReplaceDeviceStep>;

struct Step {
  std::string number; // "3", or "5.2" inside a repeat
  SourceLoc loc;
  std::string kind;   // the YAML key: "pd", "wait_until", ...
  std::string comment;
  StepAction action;
};

// Checks over the whole run (the top-level `expect:`).
enum class RunMetric {
  MaxTrackingErrorDeg, // max |tracking error| over all cycles
  Moves,               // number of executed move commands
  MovesCompleted,      // of which reached Done
  MaxTravelS,          // longest travel time of a move (manual 3.5.2 (1))
  MaxSettlingS,        // longest settling time (2); a move that never settled counts as infinite
  MaxPositioningS,     // longest positioning time (4)
  MaxTemperatureC,
  MinSupplyV,
  MaxSupplyV,
};

struct RunCheck {
  RunMetric metric;
  std::string key;
  Range range; // a plain number means "at most" for the max_* metrics, "exactly" for counts
  SourceLoc loc;
};

// `device:` besides its world keys (supply, ambient: WorldSetup).
struct DeviceSetup {
  std::optional<std::string> nvm_image_path; // resolved against the scenario's folder
  SourceLoc nvm_image_loc;
  std::vector<IsduWriteStep> isdu;          // acyclic writes at start-up
};

// `sim:` besides the physics step and the thermal time scale (WorldSpec).
struct SimSetup {
  double cycle_s = 0.002;
};

struct Scenario {
  std::string file;
  std::string name;
  // `model`, `load`, `mounting`, `world`, and `device:`'s supply and ambient
  // (A-SCN-32); `sim:`'s physics_dt_s and thermal_time_scale; `run
  // --model` is applied to `world.module`.
  WorldSetup world;
  DeviceSetup device;
  SimSetup sim;
  bool stop_on_failure = false; // default: a failed check is recorded and the run goes on
  std::vector<Step> steps;
  std::vector<RunCheck> expect;
};

} // namespace sreh
