// Named ids of the parameter table's rows (issue 13: the table is the only
// place an index is written). Code outside the table names a parameter by
// what it is, `param::MotionSet{n}.tolerance`, `param::kPositionZero`; the
// row (type, raw unit, scale, range, default) comes from the table, and a
// test checks that every id here names the row it says.
#pragma once
#include <cstdint>

#include "device_logic/parameter_table.hpp"

namespace sreh {

struct ParamId {
  uint16_t index;
  uint8_t subindex;
  constexpr bool operator==(const ParamId&) const = default;
};

namespace param {

inline constexpr ParamId kSystemCommand{2, 0};            // manual 6.6
inline constexpr ParamId kProductText{20, 0};             // manual 6.5
inline constexpr ParamId kApplicationTag{24, 0};          // manual 6.5
inline constexpr ParamId kErrorCounter{32, 0};            // manual 6.4
inline constexpr ParamId kDeviceStatus{36, 0};            // manual 6.4
inline constexpr ParamId kDetailedDeviceStatus{37, 0};    // manual 6.4
inline constexpr ParamId kPositionLimitMin{81, 1};        // manual 6.2
inline constexpr ParamId kPositionLimitMax{81, 2};
inline constexpr ParamId kPositionLimitActive{81, 3};
inline constexpr ParamId kPositiveDirection{82, 0};       // manual 6.2, 4.2
inline constexpr ParamId kLedBandMode{83, 0};             // manual 6.2, 3.1
inline constexpr ParamId kMotorVoltageMin{85, 1};         // manual 6.2
inline constexpr ParamId kMotorVoltageMax{85, 2};
inline constexpr ParamId kPositionZero{86, 0};            // manual 6.2, 4.3
inline constexpr ParamId kTrackingErrorMax{87, 1};        // manual 6.2 (raw unit: A-PARAM-1)
inline constexpr ParamId kTrackingErrorActive{87, 2};
inline constexpr ParamId kMoveCount{96, 0};               // manual 6.3 (DE: moves)
inline constexpr ParamId kTotalOperatingTime{97, 1};      // manual 6.3, minutes
inline constexpr ParamId kOperatingTimeMotorOn{97, 2};
inline constexpr ParamId kOperatingTimeMoving{97, 3};
// Maximum temperature ever (98) and since the last reset (99, command 160), manual 6.3.
struct MaxTemperature {
  ParamId operating_time, temperature;
};
inline constexpr MaxTemperature kMaxTemperatureEver{{98, 1}, {98, 2}};
inline constexpr MaxTemperature kMaxTemperatureResettable{{99, 1}, {99, 2}};
inline constexpr ParamId kTimeWithTemperatureWarning{100, 0}; // manual 6.3, minutes
inline constexpr ParamId kProcessDataInImage{40, 0};      // manual 6.4
inline constexpr ParamId kProcessDataOutImage{41, 0};     // manual 6.4
inline constexpr ParamId kTemperature{112, 0};            // manual 6.4
inline constexpr ParamId kMotorVoltage{113, 0};           // manual 6.4
inline constexpr uint16_t kErrorCauses = 114;             // manual 6.4: record, subindex 1..8
inline constexpr uint16_t kWarningCauses = 115;           // manual 6.4: record, subindex 1..3
inline constexpr ParamId kBootModeStatus{17343, 0};       // manual 6.4, 9

// Motion parameter set n = index 64 + n (manual 6.2, 3.5).
struct MotionSet {
  ParamId speed, acceleration, jerk, load, tolerance, waiting_time, settling_timeout, settling_timeout_active;
  constexpr explicit MotionSet(int n)
      : speed{idx(n), 1}, acceleration{idx(n), 2}, jerk{idx(n), 3}, load{idx(n), 4}, tolerance{idx(n), 5},
        waiting_time{idx(n), 6}, settling_timeout{idx(n), 7}, settling_timeout_active{idx(n), 8} {}

 private:
  static constexpr uint16_t idx(int n) { return static_cast<uint16_t>(64 + n); }
};
inline constexpr int kMotionSets = 8; // sets 0..7

// The causes of error bits 7..0 (114.1..8) and warning bits 7..5 (115.1..3), manual 6.4.
constexpr ParamId error_cause(int subindex) { return {kErrorCauses, static_cast<uint8_t>(subindex)}; }
constexpr ParamId warning_cause(int subindex) { return {kWarningCauses, static_cast<uint8_t>(subindex)}; }

} // namespace param

// The table row of an id; throws std::logic_error if there is none (a wrong id is a bug).
const ParameterEntry& parameter_row(ParamId id);
// Raw wire value <-> display value through the row's scale (e.g. 0.1 deg/s per LSB).
double raw_to_display(ParamId id, int64_t raw);
// Nearest raw value to a display value, clamped to the row's range.
int64_t display_to_raw(ParamId id, double display);
// The row's range and default in display units.
double display_min(ParamId id);
double display_max(ParamId id);
double display_default(ParamId id);

} // namespace sreh
