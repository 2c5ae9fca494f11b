// The one table of codes (issue 39): every cause of manual 7.2 / 7.3 and
// every ISDU error code named, with a remedy, and found from wherever a code
// appears (process data bytes, index 37 events, ISDU answers).
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "device_logic/fault_names.hpp"
#include "device_logic/isdu.hpp"

namespace sreh {
namespace {

// Manual 7.2 / 7.3: 20 error causes, 4 warning causes, each with a name and
// a remedy, the subindex that of its bit (7.1: bit 7 is 114.1 .. bit 0 114.8).
TEST(FaultNames, EveryCauseOfManual72And73HasANameAndARemedy) {
  int errors = 0, warnings = 0;
  std::set<std::tuple<EventType, int, int>> seen;
  for (const CauseDefinition& c : kCauses) {
    (c.type == EventType::Error ? errors : warnings) += 1;
    EXPECT_FALSE(c.name.empty());
    EXPECT_FALSE(c.remedy.empty()) << c.name;
    EXPECT_EQ(c.subindex, 8 - c.bit) << c.name;
    EXPECT_TRUE(seen.insert({c.type, c.bit, c.code}).second) << "twice: " << c.name;
  }
  EXPECT_EQ(errors, 20);
  EXPECT_EQ(warnings, 4);
  for (uint8_t bit = 0; bit < 8; ++bit) EXPECT_FALSE(causes_of_bit(EventType::Error, bit).empty()) << int{bit};
  for (uint8_t bit = 5; bit < 8; ++bit) EXPECT_FALSE(causes_of_bit(EventType::Warning, bit).empty()) << int{bit};
}

// The cause codes the device sets (faults.hpp cause::) are the table's rows.
TEST(FaultNames, TheCodesTheDeviceSetsAreInTheTable) {
  const auto error = [](ErrorBit b, uint8_t code) { return find_cause(EventType::Error, static_cast<uint8_t>(b), code); };
  ASSERT_NE(error(ErrorBit::TrackingError, cause::kTrackingError), nullptr);
  EXPECT_EQ(error(ErrorBit::TrackingError, cause::kTrackingError)->name, "Position tracking error");
  EXPECT_NE(error(ErrorBit::DeviceError, cause::kInternalConfiguration), nullptr);
  EXPECT_NE(error(ErrorBit::OutputStage, cause::kStateMachineError), nullptr);
  EXPECT_NE(error(ErrorBit::Temperature, cause::kOverTemperature), nullptr);
  EXPECT_NE(error(ErrorBit::MotorVoltage, cause::kVoltageHigh), nullptr);
  EXPECT_NE(error(ErrorBit::InvalidCommand, cause::kOutputsInvalid), nullptr);
  EXPECT_NE(error(ErrorBit::InvalidParameter, cause::kRelativeAndShortestPath), nullptr);
  EXPECT_NE(error(ErrorBit::Positioning, cause::kSettlingTimeout), nullptr);
  EXPECT_EQ(error(ErrorBit::InvalidCommand, 3), nullptr); // 114.6 has no code 3 (manual 7.2)
  EXPECT_NE(find_cause(EventType::Warning, static_cast<uint8_t>(WarningBit::Positioning), cause::kLeftToleranceWindow),
            nullptr);
}

// Every event of index 37 (A-EVT-1) leads to the causes it stands for.
TEST(FaultNames, EveryEventFindsItsCauses) {
  const auto check = [](const EventDefinition& e) {
    ASSERT_EQ(find_event(e.code), &e);
    EXPECT_FALSE(causes_of_bit(e.type, e.bit).empty()) << e.name;
    if (e.cause_code) {
      EXPECT_NE(find_cause(e.type, e.bit, e.cause_code), nullptr) << e.name;
    }
  };
  for (const EventDefinition& e : kErrorEvents) check(e);
  for (const EventDefinition& e : kWarningEvents) check(e);
  EXPECT_EQ(find_event(0x8CA3)->bit, 3); // position tracking error, 114.5
  EXPECT_EQ(find_event(0x1234), nullptr);
}

// What run and JUnit print for the process data's bytes (issue 39).
TEST(FaultNames, ByteTextsNameEveryBit) {
  EXPECT_EQ(error_byte_text(0), "0");
  EXPECT_EQ(error_byte_text(8), "8 (position tracking error, 114.5)");
  EXPECT_EQ(error_byte_text(1), "1 (settling-timeout, 114.8)");
  EXPECT_EQ(error_byte_text(0x0C), "12 (invalid command / communication, 114.6; position tracking error, 114.5)");
  EXPECT_EQ(warning_byte_text(0x20), "32 (exit position tolerance window, 115.3)");
  EXPECT_EQ(warning_byte_text(0x40), "64 (motor voltage, 115.2)");
  EXPECT_EQ(warning_byte_text(0x01), "1 (unused bit 0)");
}

TEST(FaultNames, MidSentenceKeepsProperNames) {
  EXPECT_EQ(mid_sentence("Position tracking error"), "position tracking error");
  EXPECT_EQ(mid_sentence("SetOrigin from invalid state"), "SetOrigin from invalid state");
  EXPECT_EQ(mid_sentence("IO-Link"), "IO-Link");
  EXPECT_EQ(mid_sentence(""), "");
}

// iolink.md: every ISDU error code with its IO-Link name, when this module
// answers it and a remedy.
TEST(FaultNames, EveryIsduErrorHasANameAndARemedy) {
  for (uint16_t code : {kIsduApplicationError, kIsduIndexNotAvailable, kIsduSubindexNotAvailable,
                        kIsduServiceTempUnavailable, kIsduLocalControl, kIsduDeviceControl, kIsduAccessDenied,
                        kIsduValueOutOfRange, kIsduValueAboveLimit, kIsduValueBelowLimit, kIsduLengthOverrun,
                        kIsduLengthUnderrun, kIsduFunctionUnavailable, kIsduFunctionTempUnavailable,
                        kIsduInvalidParameterSet, kIsduInconsistentParameterSet, kIsduApplicationNotReady}) {
    const IsduErrorDefinition* e = find_isdu_error(code);
    ASSERT_NE(e, nullptr) << code;
    EXPECT_FALSE(e->name.empty() || e->when.empty() || e->remedy.empty()) << code;
  }
  EXPECT_EQ(isdu_errors().size(), 17u);
  EXPECT_EQ(isdu_error_label(0x8030), "0x8030 (Parameter value out of range)");
  EXPECT_EQ(find_isdu_error(0x1234), nullptr);
}

} // namespace
} // namespace sreh
