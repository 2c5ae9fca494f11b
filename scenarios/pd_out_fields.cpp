#include "scenarios/pd_out_fields.hpp"

#include <limits>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "device_logic/units.hpp"

namespace sreh {
namespace {

// The command bits of the table, by name: where each goes in the update and in the frame.
struct Bit {
  std::string_view name;
  std::optional<bool> PdOutUpdate::*update;
  bool ProcessDataOut::*out;
};
constexpr Bit kBits[] = {
    {"shortest_path", &PdOutUpdate::shortest_path, &ProcessDataOut::shortest_path},
    {"relative", &PdOutUpdate::relative, &ProcessDataOut::relative},
    {"set_origin", &PdOutUpdate::set_origin, &ProcessDataOut::set_origin},
    {"reset_error", &PdOutUpdate::reset_error, &ProcessDataOut::reset_error},
    {"stop", &PdOutUpdate::stop, &ProcessDataOut::stop},
    {"move", &PdOutUpdate::move, &ProcessDataOut::move},
    {"motor_on", &PdOutUpdate::motor_on, &ProcessDataOut::motor_on},
};

const Bit& bit_named(std::string_view name) {
  for (const Bit& b : kBits) {
    if (b.name == name) return b;
  }
  throw std::logic_error(fmt::format("process data out: no member for the table's bit '{}'", name));
}

int32_t read_target(const PdFieldSource& in, const std::string& what, std::string_view raw_key) {
  if (in.has("target_deg") && in.has(raw_key)) in.fail(raw_key, what + ": give target_deg or target_raw, not both");
  if (in.has("target_deg")) {
    const double deg = in.number("target_deg", -kWireLimitDeg, kWireLimitDeg);
    const int64_t counts = deg_to_wire_counts(deg);
    if (counts < std::numeric_limits<int32_t>::min() || counts > std::numeric_limits<int32_t>::max()) {
      in.fail("target_deg", fmt::format("{}.target_deg: {} deg does not fit the int32 wire position (manual 2.5)", what, deg));
    }
    return static_cast<int32_t>(counts);
  }
  return static_cast<int32_t>(in.integer(raw_key, std::numeric_limits<int32_t>::min(), std::numeric_limits<int32_t>::max()));
}

} // namespace

const std::vector<std::string_view>& pd_out_keys() {
  static const std::vector<std::string_view> keys = [] {
    std::vector<std::string_view> k{"target_deg"};
    for (const PdField& f : kPdOutFields) k.push_back(f.name);
    return k;
  }();
  return keys;
}

PdOutUpdate read_pd_out(const PdFieldSource& in, const std::string& what) {
  PdOutUpdate u;
  for (const PdField& f : kPdOutFields) {
    switch (f.type) {
      case PdFieldType::Int32: // the target position, also given in degrees
        if (in.has(f.name) || in.has("target_deg")) u.target_raw = read_target(in, what, f.name);
        break;
      case PdFieldType::UInt8: // the wire carries any octet; the device judges it
        if (in.has(f.name)) {
          u.parameter_set = static_cast<uint8_t>(in.integer(f.name, 0, (1 << f.bit_length) - 1));
        }
        break;
      case PdFieldType::Bool:
        if (in.has(f.name)) u.*bit_named(f.name).update = in.boolean(f.name);
        break;
    }
  }
  return u;
}

void apply_pd_out(const PdOutUpdate& u, ProcessDataOut& out) {
  if (u.target_raw) out.target_raw = *u.target_raw;
  if (u.parameter_set) out.parameter_set = *u.parameter_set;
  for (const Bit& b : kBits) {
    if (u.*b.update) out.*b.out = *(u.*b.update);
  }
}

} // namespace sreh
