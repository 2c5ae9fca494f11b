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
};
// By error bit number (manual 2.4).
inline constexpr std::array<EventDefinition, 8> kErrorEvents{{
    {0x8CA0, EventType::Error, "Positioning error", "7.2 (114.8)"},
    {0x8CA1, EventType::Error, "Invalid parameter", "7.2 (114.7)"},
    {0x8CA2, EventType::Error, "Invalid command / communication", "7.2 (114.6)"},
    {0x8CA3, EventType::Error, "Position tracking error", "7.2 (114.5)"},
    {0x5100, EventType::Error, "Motor voltage (general power supply fault)", "7.2 (114.4)"},
    {0x4000, EventType::Error, "Temperature fault", "7.2 (114.3)"},
    {0x8CA6, EventType::Error, "Output stage / trajectory / state machine", "7.2 (114.2)"},
    {0x6320, EventType::Error, "Device error (parameter / configuration)", "7.2 (114.1)"},
}};
inline constexpr EventDefinition kTemperatureWarningEvent{0x4210, EventType::Warning,
                                                          "Device temperature over-run", "7.3 (115.1)"};
inline constexpr EventDefinition kVoltageLowWarningEvent{0x5111, EventType::Warning,
                                                         "Primary supply voltage under-run", "7.3 (115.2)"};
inline constexpr EventDefinition kVoltageHighWarningEvent{0x5110, EventType::Warning,
                                                          "Primary supply voltage over-run", "7.3 (115.2)"};
inline constexpr EventDefinition kToleranceWindowWarningEvent{0x8CB5, EventType::Warning,
                                                              "Left the tolerance window", "7.3 (115.3)"};
inline constexpr std::array<EventDefinition, 4> kWarningEvents{
    {kTemperatureWarningEvent, kVoltageLowWarningEvent, kVoltageHighWarningEvent, kToleranceWindowWarningEvent}};

} // namespace sreh
