// Names of the ISDU error codes (iolink.md): one table for every output
// (run, reports, serve, Python).
#include "device_logic/isdu.hpp"

#include <array>
#include <cstdio>
#include <span>

namespace sreh {
namespace {

// The IO-Link name (iolink.md), when this module answers the code (from
// its ISDU handling) and what to do (A-CODES-2: the remedies are the twin's
// advice; IO-Link names the codes only).
constexpr std::array<IsduErrorDefinition, 17> kIsduErrors{{
    {kIsduApplicationError, "Device application error", "not answered by this module (denied, no detail)",
     "Read the module's state and error bytes; retry when it is in Ready or Motor Off."},
    {kIsduIndexNotAvailable, "Index not available", "the index does not exist",
     "Check the index against the parameter table (manual chapter 6, `sreh-twin params`)."},
    {kIsduSubindexNotAvailable, "Subindex not available",
     "the subindex does not exist, or subindex access not supported",
     "Check the subindex against the parameter table (manual chapter 6); read a record whole with subindex 0."},
    {kIsduServiceTempUnavailable, "Service temporarily not available",
     "not accessible in the current state (boot mode, switched off)",
     "Wait for the module to be powered and in normal mode (not boot mode), then repeat the request."},
    {kIsduLocalControl, "Service temporarily not available - local control", "not answered by this module",
     "Repeat the request once local control has ended."},
    {kIsduDeviceControl, "Service temporarily not available - device control", "not answered by this module",
     "Repeat the request once the remotely triggered operation has ended."},
    {kIsduAccessDenied, "Access denied",
     "a write to a read-only index, a read of a write-only one (index 2)",
     "Check the access of the index in the parameter table (r, rw or w)."},
    {kIsduValueOutOfRange, "Parameter value out of range", "a value outside the parameter's range",
     "Write a value inside the range the parameter table gives (manual chapter 6); mind the unit of one step, "
     "e.g. 0.1 deg/s."},
    {kIsduValueAboveLimit, "Parameter value above limit", "a value above the parameter's limit",
     "Write a smaller value (manual chapter 6)."},
    {kIsduValueBelowLimit, "Parameter value below limit", "a value below the parameter's limit",
     "Write a larger value (manual chapter 6)."},
    {kIsduLengthOverrun, "Parameter length overrun", "written data longer than the type",
     "Send as many octets as the parameter's type has (manual chapter 6)."},
    {kIsduLengthUnderrun, "Parameter length underrun", "written data shorter than the type",
     "Send as many octets as the parameter's type has (manual chapter 6)."},
    {kIsduFunctionUnavailable, "Function unavailable", "an unknown system command",
     "Use a system command the module knows (manual 6.6, iolink.md)."},
    {kIsduFunctionTempUnavailable, "Function temporarily unavailable", "a known command at the wrong moment",
     "Send the command in the order IO-Link asks for (e.g. ParamDownloadEnd only after ParamDownloadStart)."},
    {kIsduInvalidParameterSet, "Invalid parameter set", "a single write collides with other settings",
     "Change the colliding parameters together in a block download (ParamDownloadStart ... ParamDownloadEnd)."},
    {kIsduInconsistentParameterSet, "Inconsistent parameter set",
     "the check at the end of a block download failed",
     "Correct the downloaded set so that its values agree (e.g. lower limit below upper limit); the old set stays."},
    {kIsduApplicationNotReady, "Application not ready", "not answered by this module",
     "Repeat the request when the module has started."},
}};

} // namespace

std::span<const IsduErrorDefinition> isdu_errors() { return kIsduErrors; }

const IsduErrorDefinition* find_isdu_error(uint16_t code) {
  for (const IsduErrorDefinition& e : kIsduErrors)
    if (e.code == code) return &e;
  return nullptr;
}

std::string_view isdu_error_name(uint16_t code) {
  const IsduErrorDefinition* e = find_isdu_error(code);
  return e ? e->name : "ISDU error";
}

std::string isdu_error_label(uint16_t code) {
  char hex[8];
  std::snprintf(hex, sizeof hex, "0x%04X", code);
  return std::string(hex) + " (" + std::string(isdu_error_name(code)) + ")";
}

} // namespace sreh
