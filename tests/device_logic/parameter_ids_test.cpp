// Named parameter ids (issue 13) name the rows they say they name, and the
// conversions follow the table's scale and range (manual 6.2).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string_view>

#include "device_logic/parameter_ids.hpp"

namespace sreh {
namespace {

std::string_view name_of(ParamId id) { return parameter_row(id).name; }

TEST(ParameterIds, MotionSetMembersNameTheirRows_6_2) {
  for (int n = 0; n < param::kMotionSets; ++n) {
    const param::MotionSet set{n};
    EXPECT_EQ(set.speed.index, 64 + n);
    EXPECT_EQ(name_of(set.speed), "Maximum speed");
    EXPECT_EQ(name_of(set.acceleration), "Acceleration factor");
    EXPECT_EQ(name_of(set.jerk), "Jerk factor");
    EXPECT_EQ(name_of(set.load), "Load (mass moment of inertia)");
    EXPECT_EQ(name_of(set.tolerance), "Position tolerance");
    EXPECT_EQ(name_of(set.waiting_time), "Waiting time");
    EXPECT_EQ(name_of(set.settling_timeout), "Settling-timeout");
    EXPECT_EQ(name_of(set.settling_timeout_active), "Settling-timeout active");
  }
}

TEST(ParameterIds, PlainIdsNameTheirRows_6) {
  EXPECT_EQ(name_of(param::kPositiveDirection), "Positive direction of rotation");
  EXPECT_EQ(name_of(param::kPositionZero), "Position zero");
  EXPECT_EQ(name_of(param::kTrackingErrorMax), "Max. position tracking error");
  EXPECT_EQ(name_of(param::kTrackingErrorActive), "Position tracking error monitoring active");
  EXPECT_EQ(name_of(param::kLedBandMode), "LED band mode");
  EXPECT_EQ(name_of(param::kMotorVoltageMin), "Minimum");
  EXPECT_EQ(parameter_row(param::kMotorVoltageMin).record_name, "Valid range of motor voltage");
  EXPECT_EQ(parameter_row(param::kPositionLimitMax).record_name, "Position limit");
  EXPECT_EQ(name_of(param::kPositionLimitActive), "Position limitation active");
  EXPECT_EQ(name_of(param::kErrorCounter), "Error counter");
  EXPECT_EQ(name_of(param::kDeviceStatus), "Device status");
  EXPECT_EQ(name_of(param::kTemperature), "Temperature");
  EXPECT_EQ(name_of(param::kMotorVoltage), "Motor voltage");
  EXPECT_EQ(name_of(param::kProductText), "Product text");
  EXPECT_EQ(name_of(param::error_cause(5)), "Cause for error bit 3");
  EXPECT_NO_THROW(parameter_row(param::warning_cause(3)));
  EXPECT_NO_THROW(parameter_row(param::kMoveCount));
  EXPECT_NO_THROW(parameter_row(param::kSystemCommand));
  EXPECT_THROW(parameter_row(ParamId{64, 9}), std::logic_error);
}

TEST(ParameterIds, ConversionsFollowTheTable_6_2) {
  const param::MotionSet set1{1};
  EXPECT_DOUBLE_EQ(raw_to_display(set1.speed, 30000), 3000.0);   // 0.1 deg/s per LSB
  EXPECT_EQ(display_to_raw(set1.speed, 4299.96), 43000);
  EXPECT_EQ(display_to_raw(set1.speed, 1e9), 43000);              // clamped to the range
  EXPECT_EQ(display_to_raw(set1.speed, 0.0), 1);
  EXPECT_DOUBLE_EQ(display_max(set1.speed), 4300.0);
  EXPECT_DOUBLE_EQ(display_default(set1.speed), 3000.0);
  EXPECT_DOUBLE_EQ(display_default(param::MotionSet{0}.speed), 30.0);
  EXPECT_EQ(display_to_raw(set1.tolerance, 0.1), 146);            // 2^-19 rev per LSB (A-PARAM-2)
  EXPECT_DOUBLE_EQ(raw_to_display(param::kTrackingErrorMax, 10), 1.0); // 0.1 deg (A-PARAM-1)
}

} // namespace
} // namespace sreh
