// Errors and warnings as the manual numbers them (2.4, 7.2, 7.3): one cause
// code per bit, sticky errors with an explicit reset, self-clearing warnings
// (docs/style.md 4). The cause codes are the values of indices 114.x / 115.x.
#pragma once
#include <array>
#include <cstdint>
#include <string_view>

namespace sreh {

// Error bits of the process data error byte (manual 2.4).
enum class ErrorBit : uint8_t {
  Positioning = 0,       // 114.8
  InvalidParameter = 1,  // 114.7
  InvalidCommand = 2,    // 114.6
  TrackingError = 3,     // 114.5
  MotorVoltage = 4,      // 114.4
  Temperature = 5,       // 114.3
  OutputStage = 6,       // 114.2
  DeviceError = 7,       // 114.1
};

// Warning bits of the warning byte (manual 2.4).
enum class WarningBit : uint8_t {
  Positioning = 5,  // 115.3
  MotorVoltage = 6, // 115.2
  Temperature = 7,  // 115.1
};

// Cause codes, manual 7.2 / 7.3.
namespace cause {
inline constexpr uint8_t kInternalConfiguration = 1;   // 114.1
inline constexpr uint8_t kOutputStageOvercurrent = 1;  // 114.2
inline constexpr uint8_t kTrajectoryError = 2;         // 114.2
inline constexpr uint8_t kStateMachineError = 3;       // 114.2
inline constexpr uint8_t kOverTemperature = 1;         // 114.3
inline constexpr uint8_t kVoltageLow = 1;              // 114.4, 115.2
inline constexpr uint8_t kVoltageHigh = 2;             // 114.4, 115.2
inline constexpr uint8_t kTrackingError = 64;          // 114.5
inline constexpr uint8_t kMotorSwitchedOff = 1;        // 114.6
inline constexpr uint8_t kOperationAborted = 2;        // 114.6
inline constexpr uint8_t kMoveFromInvalidState = 4;    // 114.6
inline constexpr uint8_t kSetOriginFromInvalidState = 5; // 114.6
inline constexpr uint8_t kMoveAndSetOrigin = 6;        // 114.6
inline constexpr uint8_t kConnectionInterrupted = 16;  // 114.6
inline constexpr uint8_t kOutputsInvalid = 17;         // 114.6
inline constexpr uint8_t kInvalidTarget = 1;           // 114.7
inline constexpr uint8_t kInvalidParameterSet = 2;     // 114.7
inline constexpr uint8_t kRelativeAndShortestPath = 3; // 114.7
inline constexpr uint8_t kSettlingTimeout = 1;         // 114.8
inline constexpr uint8_t kTemperatureWarning = 1;      // 115.1
inline constexpr uint8_t kLeftToleranceWindow = 1;     // 115.3
} // namespace cause

// Does this error switch the motor off? Manual 2.4 bit-field table: bits 7..3
// yes, bit 2 only for invalid process data / connection loss, bits 1, 0 no.
constexpr bool error_switches_motor_off(ErrorBit bit, uint8_t code) {
  switch (bit) {
    case ErrorBit::InvalidCommand:
      return code == cause::kConnectionInterrupted || code == cause::kOutputsInvalid ||
             code == cause::kMotorSwitchedOff; // the PLC switched it off itself (manual 7.2 code 1)
    case ErrorBit::InvalidParameter:
    case ErrorBit::Positioning:
      return false;
    default:
      return true;
  }
}

// Active causes: one code per bit, 0 when inactive (manual 6.4 note).
struct FaultSet {
  std::array<uint8_t, 8> error_cause{};   // by error bit number
  std::array<uint8_t, 8> warning_cause{}; // by warning bit number (5..7 used)

  uint8_t error_byte() const {
    uint8_t b = 0;
    for (int i = 0; i < 8; ++i) b = static_cast<uint8_t>(b | (error_cause[i] ? (1u << i) : 0u));
    return b;
  }
  uint8_t warning_byte() const {
    uint8_t b = 0;
    for (int i = 0; i < 8; ++i) b = static_cast<uint8_t>(b | (warning_cause[i] ? (1u << i) : 0u));
    return b;
  }
  bool any_error() const { return error_byte() != 0; }
  bool any_warning() const { return warning_byte() != 0; }
  uint8_t error(ErrorBit b) const { return error_cause[static_cast<int>(b)]; }
  uint8_t warning(WarningBit b) const { return warning_cause[static_cast<int>(b)]; }
  void set_warning(WarningBit b, uint8_t code) { warning_cause[static_cast<int>(b)] = code; } // 0 clears
  bool operator==(const FaultSet&) const = default;
};

// The events the device reports in Detailed Device Status (37) and, for the
// IODD-like export, describes (A-EVT-1: iolink.md standard codes where one
// fits, vendor codes 0x8CAx / 0x8CBx otherwise).
enum class EventType { Warning, Error };
struct EventDefinition {
  uint16_t code;
  EventType type;
  std::string_view name;
  std::string_view section; // manual section of the cause
  uint8_t bit;              // of the error / warning byte (manual 2.4)
  uint8_t cause_code = 0;   // the one cause it stands for; 0: every cause of the bit
};

// Every cause the module reports (issue 39), the manual's tables 7.2 and 7.3
// in its words (A-CODES-1): the error or warning byte's bit (2.4), the subindex of
// 114 / 115 that holds the cause code (7.1), the code, the manual's "Error
// cause" and "Description / Remedy". The one table of names for the run
// output, JUnit, reports, serve, Python and docs/errors.md
// (device_logic/fault_names.hpp looks things up in it).
struct CauseDefinition {
  EventType type;
  uint8_t bit;      // of the error / warning byte (manual 2.4)
  uint8_t subindex; // 114.subindex / 115.subindex (manual 7.1)
  uint8_t code;     // the subindex's value
  std::string_view name;
  std::string_view remedy;
};
// A-CODES-1: 114.2 code 1 has no remedy in the manual (an empty cell, in DE
// and EN); 115.2 code 2 shares the cell of code 1 (a merged cell).
inline constexpr std::string_view kNoRemedyGiven = "The manual gives no remedy for this cause; contact Afag.";
inline constexpr std::array<CauseDefinition, 24> kCauses{{
    {EventType::Error, 7, 1, 1, "Internal configuration faulty", "Contact Afag."},
    {EventType::Error, 6, 2, 1, "Output stage overcurrent", kNoRemedyGiven},
    {EventType::Error, 6, 2, 2, "Trajectory error", "Contact Afag."},
    {EventType::Error, 6, 2, 3, "Error in the state machine", "Contact Afag."},
    {EventType::Error, 6, 2, 255, "Unknown error", "Contact Afag."},
    {EventType::Error, 5, 3, 1, "Overtemperature (>= 75 \u00b0C)",
     "Check the thermal connection. Longer pauses between movements. Check the mechanical structure."},
    {EventType::Error, 4, 4, 1, "Motor voltage too low",
     "The motor voltage has left the valid range when the motor is switched on. When the motor is switched off, "
     "this only results in a warning. Check the parameter set, especially the load. Check the motor supply."},
    {EventType::Error, 4, 4, 2, "Motor voltage too high",
     "Check which other units are connected to the motor supply and load it or feed back to it. Possibly set the "
     "lower/upper voltage limit less restrictively (provided this is permissible for the power supply unit and all "
     "other connected loads). In case of overvoltage: install more capacity on the motor supply or install a chopper."},
    {EventType::Error, 3, 5, 64, "Position tracking error",
     "Check the parameter set, especially the load. Check the motor supply. With reduced motor voltage (< 24 V), "
     "the maximum achievable speed is reduced proportionally to the voltage. Check that the speed is not set too "
     "high. Check the mechanical structure (collision, friction)."},
    {EventType::Error, 2, 6, 1, "Motor unexpectedly switched off",
     "The motor must not be switched off in the Busy and Done states."},
    {EventType::Error, 2, 6, 2, "Operation aborted",
     "The Move process data bit must remain set until the Done state is reached."},
    {EventType::Error, 2, 6, 4, "Move command from invalid state",
     "An operation may only be started in the Ready state."},
    {EventType::Error, 2, 6, 5, "SetOrigin from invalid state",
     "Zero setting may only be carried out in the Ready state."},
    {EventType::Error, 2, 6, 6, "Move command and SetOrigin simultaneously",
     "The two bits Move and SetOrigin must not be set at the same time."},
    {EventType::Error, 2, 6, 16, "Connection interruption IO-Link",
     "A connection interruption is only considered an error if the motor was switched on before the "
     "interruption. Check the wiring. Check the configuration of the IO-Link master. Check the PLC."},
    {EventType::Error, 2, 6, 17, "Process data outputs marked as invalid",
     "Invalid process data outputs are only evaluated as errors if the motor was switched on before the "
     "interruption. Check the IO-Link master and the PLC."},
    {EventType::Error, 1, 7, 1, "Invalid target position",
     "The target position is outside the specified range. Check the PLC programme. Check the position range "
     "(index 81). Check that the Relative and Shortest Path process data bits have been set correctly before "
     "starting the movement."},
    {EventType::Error, 1, 7, 2, "Invalid parameter set",
     "Check whether a valid parameter set (0 to 7) has been selected in the process data. This value must be "
     "present at the latest when Move is set and at least until the module changes to the Busy state."},
    {EventType::Error, 1, 7, 3, "Relative and Shortest Path simultaneously",
     "The two modes are mutually exclusive: at most one of the two bits may be set. The bits must be present at "
     "the latest when Move is set and at least until the module changes to the Busy state."},
    {EventType::Error, 0, 8, 1, "Settling-timeout",
     "Check the parameter set, especially the load. Check the motor supply. Check the mechanical structure "
     "(collision, friction). If necessary, set the timeout in the selected parameter set higher (index 64..71)."},
    {EventType::Warning, 7, 1, 1, "Temperature warning (>= 70 \u00b0C)", "See overtemperature (error index 114.3)."},
    {EventType::Warning, 6, 2, 1, "Motor voltage too low", "See voltage error (error index 114.4)."},
    {EventType::Warning, 6, 2, 2, "Motor voltage too high", "See voltage error (error index 114.4)."},
    {EventType::Warning, 5, 3, 1, "Exit position tolerance window",
     "After the positioning was completed, the tolerance window was left again. This can occur if the waiting "
     "time is set too short and therefore the position is found to be stable too early: increase the waiting time "
     "in the parameter set (index 64..71). Leaving the tolerance window can also be caused by external influences "
     "(a moment acting on the flange; vibration that cannot be sufficiently compensated, especially with large "
     "loads): ideally remedy the external influence; depending on the accuracy requirements, the tolerance window "
     "may be set less narrow. The warning disappears automatically on the next operation or as soon as the motor "
     "is switched off."},
}};

// The bits of the error and warning bytes as the manual's bit-field tables
// name them (2.4), by bit number; empty: not used.
inline constexpr std::array<std::string_view, 8> kErrorBitNames{
    "Positioning error", "Invalid parameter", "Invalid command / communication", "Position tracking error",
    "Motor voltage",     "Temperature error", "Final stage/trajectory",          "Device error"};
inline constexpr std::array<std::string_view, 8> kWarningBitNames{
    "", "", "", "", "", "Positioning warning", "Motor voltage", "Temperature warning"};
// By error bit number (manual 2.4).
inline constexpr std::array<EventDefinition, 8> kErrorEvents{{
    {0x8CA0, EventType::Error, "Positioning error", "7.2 (114.8)", 0},
    {0x8CA1, EventType::Error, "Invalid parameter", "7.2 (114.7)", 1},
    {0x8CA2, EventType::Error, "Invalid command / communication", "7.2 (114.6)", 2},
    {0x8CA3, EventType::Error, "Position tracking error", "7.2 (114.5)", 3},
    {0x5100, EventType::Error, "Motor voltage (general power supply fault)", "7.2 (114.4)", 4},
    {0x4000, EventType::Error, "Temperature fault", "7.2 (114.3)", 5},
    {0x8CA6, EventType::Error, "Output stage / trajectory / state machine", "7.2 (114.2)", 6},
    {0x6320, EventType::Error, "Device error (parameter / configuration)", "7.2 (114.1)", 7},
}};
inline constexpr EventDefinition kTemperatureWarningEvent{0x4210, EventType::Warning,
                                                          "Device temperature over-run", "7.3 (115.1)", 7};
inline constexpr EventDefinition kVoltageLowWarningEvent{0x5111, EventType::Warning,
                                                         "Primary supply voltage under-run", "7.3 (115.2)", 6,
                                                         cause::kVoltageLow};
inline constexpr EventDefinition kVoltageHighWarningEvent{0x5110, EventType::Warning,
                                                          "Primary supply voltage over-run", "7.3 (115.2)", 6,
                                                          cause::kVoltageHigh};
inline constexpr EventDefinition kToleranceWindowWarningEvent{0x8CB5, EventType::Warning,
                                                              "Left the tolerance window", "7.3 (115.3)", 5};
inline constexpr std::array<EventDefinition, 4> kWarningEvents{
    {kTemperatureWarningEvent, kVoltageLowWarningEvent, kVoltageHighWarningEvent, kToleranceWindowWarningEvent}};

} // namespace sreh
