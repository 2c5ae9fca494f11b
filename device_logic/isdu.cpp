// Names of the ISDU error codes (iolink.md): one table for every output
// (run, reports, serve, Python).
#include "device_logic/isdu.hpp"

#include <array>
#include <cstdio>

namespace sreh {
namespace {

struct ErrorName {
  uint16_t code;
  std::string_view name;
};

constexpr std::array<ErrorName, 17> kErrorNames{{
    {kIsduApplicationError, "Device application error"},
    {kIsduIndexNotAvailable, "Index not available"},
    {kIsduSubindexNotAvailable, "Subindex not available"},
    {kIsduServiceTempUnavailable, "Service temporarily not available"},
    {kIsduLocalControl, "Service temporarily not available - local control"},
    {kIsduDeviceControl, "Service temporarily not available - device control"},
    {kIsduAccessDenied, "Access denied"},
    {kIsduValueOutOfRange, "Parameter value out of range"},
    {kIsduValueAboveLimit, "Parameter value above limit"},
    {kIsduValueBelowLimit, "Parameter value below limit"},
    {kIsduLengthOverrun, "Parameter length overrun"},
    {kIsduLengthUnderrun, "Parameter length underrun"},
    {kIsduFunctionUnavailable, "Function unavailable"},
    {kIsduFunctionTempUnavailable, "Function temporarily unavailable"},
    {kIsduInvalidParameterSet, "Invalid parameter set"},
    {kIsduInconsistentParameterSet, "Inconsistent parameter set"},
    {kIsduApplicationNotReady, "Application not ready"},
}};

} // namespace

std::string_view isdu_error_name(uint16_t code) {
  for (const ErrorName& e : kErrorNames) {
    if (e.code == code) return e.name;
  }
  return "ISDU error";
}

std::string isdu_error_label(uint16_t code) {
  char hex[8];
  std::snprintf(hex, sizeof hex, "0x%04X", code);
  return std::string(hex) + " (" + std::string(isdu_error_name(code)) + ")";
}

} // namespace sreh
