// ISDU (acyclic) answers and the IO-Link error codes a device returns
// (ErrorCode and AdditionalCode as one 16-bit value, iolink.md).
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sreh {

inline constexpr uint16_t kIsduOk = 0;
inline constexpr uint16_t kIsduApplicationError = 0x8000;        // denied, no detail
inline constexpr uint16_t kIsduIndexNotAvailable = 0x8011;
inline constexpr uint16_t kIsduSubindexNotAvailable = 0x8012;
inline constexpr uint16_t kIsduServiceTempUnavailable = 0x8020;  // not accessible in this state
inline constexpr uint16_t kIsduLocalControl = 0x8021;
inline constexpr uint16_t kIsduDeviceControl = 0x8022;
inline constexpr uint16_t kIsduAccessDenied = 0x8023;            // write r-only / read w-only
inline constexpr uint16_t kIsduValueOutOfRange = 0x8030;
inline constexpr uint16_t kIsduValueAboveLimit = 0x8031;
inline constexpr uint16_t kIsduValueBelowLimit = 0x8032;
inline constexpr uint16_t kIsduLengthOverrun = 0x8033;
inline constexpr uint16_t kIsduLengthUnderrun = 0x8034;
inline constexpr uint16_t kIsduFunctionUnavailable = 0x8035;     // unknown system command
inline constexpr uint16_t kIsduFunctionTempUnavailable = 0x8036; // known command, wrong moment
inline constexpr uint16_t kIsduInvalidParameterSet = 0x8040;     // single write collides
inline constexpr uint16_t kIsduInconsistentParameterSet = 0x8041;// block download check failed
inline constexpr uint16_t kIsduApplicationNotReady = 0x8082;

// ISDU answer: error 0 means success; otherwise an IO-Link ISDU error code
// and no data.
struct IsduResult {
  uint16_t error = kIsduOk;
  std::vector<uint8_t> data;
  bool ok() const { return error == kIsduOk; }
};

inline IsduResult isdu_error(uint16_t code) { return IsduResult{code, {}}; }
inline IsduResult isdu_data(std::vector<uint8_t> data) { return IsduResult{kIsduOk, std::move(data)}; }

// One row of the table of ISDU error codes (isdu.cpp, docs/errors.md).
struct IsduErrorDefinition {
  uint16_t code;
  std::string_view name;   // IO-Link's (iolink.md)
  std::string_view when;   // when this module answers it
  std::string_view remedy; // what to do
};
std::span<const IsduErrorDefinition> isdu_errors();
const IsduErrorDefinition* find_isdu_error(uint16_t code); // nullptr for a code not in the table

// The IO-Link name of an ISDU error code ("Parameter value out of range"
// for 0x8030; iolink.md, IO-Link spec Annex C); "ISDU error" for a code
// this device never returns.
std::string_view isdu_error_name(uint16_t code);
// "0x8030 (Parameter value out of range)": how every output names a refusal.
std::string isdu_error_label(uint16_t code);

} // namespace sreh
