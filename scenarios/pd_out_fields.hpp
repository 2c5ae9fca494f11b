// The process data out a PLC program sets field by field (manual 2.2): one
// reader for a scenario's `pd:` step (YAML) and serve's
// PUT /v1/ports/{p}/processdata/out (JSON), driven by the layout table
// kPdOutFields (device_logic/process_data.hpp) so that a field is named,
// typed and ranged in one place: target_raw (or target_deg, converted to
// wire counts, manual 2.5), parameter_set 0..255 (8..255 are sent, the
// device rejects them: manual 7.2, 114.7 code 2), the command bits as
// booleans. Fields left out keep their value.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "device_logic/process_data.hpp"

namespace sreh {

// manual 2.5: the int32 wire position spans +-2^15 revolutions.
inline constexpr double kWireLimitDeg = 32768.0 * 360.0;

// The fields given, each optional.
struct PdOutUpdate {
  std::optional<int32_t> target_raw; // target_deg is converted to wire counts by the reader
  std::optional<uint8_t> parameter_set;
  std::optional<bool> motor_on;
  std::optional<bool> move;
  std::optional<bool> stop;
  std::optional<bool> reset_error;
  std::optional<bool> set_origin;
  std::optional<bool> relative;
  std::optional<bool> shortest_path;
};

// How one format reads a key of the request; each reader throws that
// format's error (naming the key and where) for a bad value.
class PdFieldSource {
 public:
  virtual ~PdFieldSource() = default;
  virtual bool has(std::string_view key) const = 0;
  virtual double number(std::string_view key, double lo, double hi) const = 0;
  virtual int64_t integer(std::string_view key, int64_t lo, int64_t hi) const = 0;
  virtual bool boolean(std::string_view key) const = 0;
  [[noreturn]] virtual void fail(std::string_view key, const std::string& message) const = 0;
};

// The keys a request may use: target_deg and the table's field names.
const std::vector<std::string_view>& pd_out_keys();

// Reads the fields present; `what` prefixes the messages ("3.pd",
// "processdata/out"). Does not check for unknown keys (pd_out_keys()).
PdOutUpdate read_pd_out(const PdFieldSource& in, const std::string& what);

// The fields given replace those of `out`; the others stay.
void apply_pd_out(const PdOutUpdate& update, ProcessDataOut& out);

} // namespace sreh
