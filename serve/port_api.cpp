#include "serve/port_api.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "device_logic/parameter_table.hpp"
#include "device_logic/units.hpp"
#include "scenarios/isdu_value.hpp"
#include "scenarios/pd_out_fields.hpp"
#include "scenarios/world.hpp"

namespace sreh::serve {
namespace {

bool is_text(ParamType t) { return t == ParamType::String || t == ParamType::OctetString; }

void check_keys(const Json& body, const std::vector<std::string_view>& allowed, const std::string& what) {
  for (const auto& [key, value] : body.items()) {
    bool ok = false;
    for (std::string_view a : allowed) ok = ok || key == a;
    if (!ok) {
      std::string list;
      for (std::string_view a : allowed) list += fmt::format("{}{}", list.empty() ? "" : ", ", a);
      throw RequestError(400, fmt::format("{}: unknown key '{}' (allowed: {})", what, key, list));
    }
  }
}

bool get_bool(const Json& v, const std::string& what) {
  if (v.is_boolean()) return v.get<bool>();
  if (v.is_number_integer() && (v.get<int64_t>() == 0 || v.get<int64_t>() == 1)) return v.get<int64_t>() == 1;
  throw RequestError(400, fmt::format("{}: expected true/false (or 0/1)", what));
}

double get_number(const Json& v, const std::string& what, double lo, double hi) {
  if (!v.is_number()) throw RequestError(400, fmt::format("{}: expected a number", what));
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < lo || x > hi)
    throw RequestError(400, fmt::format("{}: {} is outside {} .. {}", what, x, lo, hi));
  return x;
}

int64_t get_integer(const Json& v, const std::string& what, int64_t lo, int64_t hi) {
  if (!v.is_number_integer()) throw RequestError(400, fmt::format("{}: expected an integer", what));
  const int64_t x = v.is_number_unsigned() && v.get<uint64_t>() > static_cast<uint64_t>(std::numeric_limits<int64_t>::max())
                        ? std::numeric_limits<int64_t>::max()
                        : v.get<int64_t>();
  if (x < lo || x > hi) throw RequestError(400, fmt::format("{}: {} is outside {} .. {}", what, x, lo, hi));
  return x;
}

// The decoded process-data fields of a request body (scenarios/pd_out_fields.hpp:
// the same table and ranges as a scenario's pd: step).
class JsonPdSource final : public PdFieldSource {
 public:
  JsonPdSource(const Json& body, const std::string& what) : body_(body), what_(what) {}
  bool has(std::string_view key) const override { return body_.contains(std::string(key)); }
  double number(std::string_view key, double lo, double hi) const override {
    return get_number(body_[std::string(key)], fmt::format("{}.{}", what_, key), lo, hi);
  }
  int64_t integer(std::string_view key, int64_t lo, int64_t hi) const override {
    return get_integer(body_[std::string(key)], fmt::format("{}.{}", what_, key), lo, hi);
  }
  bool boolean(std::string_view key) const override { return get_bool(body_[std::string(key)], fmt::format("{}.{}", what_, key)); }
  [[noreturn]] void fail(std::string_view, const std::string& message) const override { throw RequestError(400, message); }

 private:
  const Json& body_;
  const std::string& what_;
};

std::vector<uint8_t> encode_typed(const Json& v, ParamType t, const std::string& what) {
  const auto [lo, hi] = detail::wire_range(t);
  return encode_number(t, get_integer(v, fmt::format("{} ({})", what, type_name(t)), lo, hi));
}

} // namespace

std::string hex_bytes(std::span<const uint8_t> bytes) {
  std::string out;
  for (uint8_t b : bytes) out += fmt::format("{:02X}", b);
  return out;
}

std::vector<uint8_t> parse_hex(const std::string& text, const std::string& what) {
  if (text.size() % 2 != 0) throw RequestError(400, fmt::format("{}: odd number of hex digits", what));
  std::vector<uint8_t> out;
  for (std::size_t i = 0; i < text.size(); i += 2) {
    unsigned v = 0;
    for (int k = 0; k < 2; ++k) {
      const char c = text[i + static_cast<std::size_t>(k)];
      unsigned d;
      if (c >= '0' && c <= '9') d = static_cast<unsigned>(c - '0');
      else if (c >= 'a' && c <= 'f') d = static_cast<unsigned>(c - 'a' + 10);
      else if (c >= 'A' && c <= 'F') d = static_cast<unsigned>(c - 'A' + 10);
      else throw RequestError(400, fmt::format("{}: '{}' is not a hex digit", what, c));
      v = v * 16 + d;
    }
    out.push_back(static_cast<uint8_t>(v));
  }
  return out;
}

// The one name table is the device's (device_logic/isdu.cpp).
std::string iolink_error_name(uint16_t code) { return std::string(isdu_error_name(code)); }

std::string iolink_error_text(uint16_t code) { return fmt::format("0x{:04X}", code); }

// 404: the index/subindex does not exist; 422: the value is wrong; 409:
// the request is right but not now or not this way (access, state).
int http_status_for(uint16_t code) {
  if (code == kIsduIndexNotAvailable || code == kIsduSubindexNotAvailable) return 404;
  if (code >= kIsduValueOutOfRange && code <= kIsduInconsistentParameterSet && code != kIsduFunctionUnavailable &&
      code != kIsduFunctionTempUnavailable)
    return 422;
  return 409;
}

bool pd_in_valid(Hub::Port& port) {
  return port.faults.link_up && port.twin.powered() && port.twin.iolink_led() == IoLinkLedMode::Operate;
}

Json fault_injection_json(const Hub::Port& port) {
  const FaultState& f = port.faults;
  const FaultState normal;
  Json list = Json::array();
  if (!f.link_up) list.push_back("link down");
  if (f.flange_blocked) list.push_back("flange blocked");
  if (f.external_torque_Nm != normal.external_torque_Nm) list.push_back(fmt::format("external torque {:g} N·m", f.external_torque_Nm));
  if (f.supply_V != port.nominal_supply_V) list.push_back(fmt::format("supply {:g} V", f.supply_V));
  if (f.ambient_C != port.nominal_ambient_C) list.push_back(fmt::format("ambient {:g} °C", f.ambient_C));
  return list;
}

Json port_summary(int p, Hub::Port& port) {
  const Telemetry tel = port.twin.telemetry();
  const ProcessDataIn in = port.twin.pd_in();
  return Json{{"port", p},
              {"device", "SREH-50-IOL"},
              {"vendor", "Afag"},
              {"state", state_name(tel.state)},
              {"led", led_name(tel.led)},
              {"position_deg", wire_counts_to_deg(in.position_raw)},
              {"pd_in_valid", pd_in_valid(port)},
              {"pd_out_valid", port.outputs_valid},
              {"time_s", port.twin.time_s()},
              {"failure", port.failure.empty() ? Json(nullptr) : Json(port.failure)},
              {"state_write_error", port.state_write_error.empty() ? Json(nullptr) : Json(port.state_write_error)},
              {"fault_injection", fault_injection_json(port)}};
}

namespace {

// A frame's fields by name, read through the layout table (kPdInFields /
// kPdOutFields): the one vocabulary of scenarios, serve and Python.
template <std::size_t N, class Row, std::size_t F>
void add_fields(Json& j, const std::array<uint8_t, N>& frame, const std::array<Row, F>& fields) {
  for (const PdField& f : fields) {
    const int64_t v = pd_field_value(frame, f);
    if (!f.deg_name.empty()) j[std::string(f.deg_name)] = wire_counts_to_deg(static_cast<int32_t>(v));
    if (f.type == PdFieldType::Bool) j[std::string(f.name)] = v != 0;
    else j[std::string(f.name)] = v;
  }
}

} // namespace

Json processdata_json(Hub::Port& port) {
  const PdInFrame in_frame = encode(port.twin.pd_in());
  const PdOutFrame out_frame = encode(port.twin.pd_out());
  Json j;
  j["in"] = Json{{"raw", hex_bytes(in_frame)}, {"valid", pd_in_valid(port)}};
  add_fields(j["in"], in_frame, kPdInFields);
  j["in"]["state"] = state_name(port.twin.telemetry().state);
  j["out"] = Json{{"raw", hex_bytes(out_frame)}, {"valid", port.outputs_valid}};
  add_fields(j["out"], out_frame, kPdOutFields);
  return j;
}

void apply_pd_out(Hub::Port& port, const Json& body) {
  const std::string what = "processdata/out";
  if (!body.is_object()) throw RequestError(400, what + ": expected a JSON object");
  std::vector<std::string_view> allowed{"raw", "valid"};
  allowed.insert(allowed.end(), pd_out_keys().begin(), pd_out_keys().end());
  check_keys(body, allowed, what);
  ProcessDataOut out = port.twin.pd_out();
  if (body.contains("raw")) {
    if (body.size() > (body.contains("valid") ? 2u : 1u))
      throw RequestError(400, what + ": 'raw' cannot be combined with decoded fields");
    if (!body["raw"].is_string()) throw RequestError(400, what + ".raw: expected a string of 12 hex digits");
    const auto bytes = parse_hex(body["raw"].get<std::string>(), what + ".raw");
    if (bytes.size() != kPdOutBytes)
      throw RequestError(400, fmt::format("{}.raw: {} octets, process data out has {} (manual 2.2)", what,
                                          bytes.size(), kPdOutBytes));
    out = decode_out(std::span<const uint8_t>(bytes));
  }
  if (!body.contains("raw")) sreh::apply_pd_out(read_pd_out(JsonPdSource(body, what), what), out);
  bool valid = port.outputs_valid;
  if (body.contains("valid")) valid = get_bool(body["valid"], what + ".valid");
  // Everything checked: apply.
  port.twin.set_pd_out(out);
  port.outputs_valid = valid;
  port.twin.set_outputs_valid(valid);
}

Json parameter_json(uint16_t index, uint8_t subindex, std::span<const uint8_t> data) {
  Json j{{"index", index}, {"subindex", subindex}};
  const ParameterEntry* row = find_parameter(index, subindex);
  if (row != nullptr) j["name"] = row->name;
  if (row != nullptr && is_text(row->type)) {
    j["value"] = row->type == ParamType::String ? Json(detail::decode_isdu_text(data)) : Json(hex_bytes(data));
  } else if (row == nullptr && subindex == 0 && is_record(index)) {
    const auto members = record_members(index);
    j["name"] = members.front()->record_name;
    Json values = Json::array();
    std::size_t at = 0;
    for (const auto* m : members) {
      const std::size_t n = wire_size(m->type);
      if (n == 0 || at + n > data.size()) {
        values = nullptr;
        break;
      }
      values.push_back(decode_number(m->type, data.subspan(at, n)));
      at += n;
    }
    j["value"] = values;
  } else if (const auto v = detail::decode_isdu_number(index, subindex, data)) {
    j["value"] = *v;
  } else {
    j["value"] = nullptr;
  }
  j["raw"] = hex_bytes(data);
  return j;
}

std::vector<uint8_t> parameter_bytes(uint16_t index, uint8_t subindex, const Json& body) {
  const std::string what = fmt::format("parameters/{}/{}", index, subindex);
  if (!body.is_object()) throw RequestError(400, what + ": expected a JSON object");
  check_keys(body, {"value", "raw"}, what);
  if (body.contains("value") == body.contains("raw")) throw RequestError(400, what + ": give exactly one of value, raw");
  if (body.contains("raw")) {
    if (!body["raw"].is_string()) throw RequestError(400, what + ".raw: expected a hex string");
    auto bytes = parse_hex(body["raw"].get<std::string>(), what + ".raw");
    if (bytes.size() > 232) throw RequestError(400, what + ".raw: more than 232 octets (ISDU maximum)");
    return bytes;
  }
  const Json& v = body["value"];
  const ParameterEntry* row = find_parameter(index, subindex);
  if (v.is_array()) {
    const auto members = record_members(index);
    if (row != nullptr || subindex != 0 || members.empty())
      throw RequestError(400, what + ".value: a list is only allowed for a whole record (subindex 0)");
    if (v.size() != members.size())
      throw RequestError(400, fmt::format("{}.value: record {} has {} members, got {} values", what, index,
                                          members.size(), v.size()));
    std::vector<uint8_t> out;
    for (std::size_t i = 0; i < members.size(); ++i) {
      if (is_text(members[i]->type)) throw RequestError(400, what + ".value: text members cannot be written as a list");
      const auto b = encode_typed(v[i], members[i]->type, fmt::format("{}.value[{}]", what, i));
      out.insert(out.end(), b.begin(), b.end());
    }
    return out;
  }
  if (row != nullptr && is_text(row->type)) {
    if (!v.is_string()) throw RequestError(400, what + ".value: expected a text");
    const std::string s = v.get<std::string>();
    if (s.size() > 232) throw RequestError(400, what + ".value: more than 232 octets (ISDU maximum)");
    return {s.begin(), s.end()};
  }
  if (row != nullptr) return encode_typed(v, row->type, what + ".value");
  if (subindex == 0 && is_record(index))
    throw RequestError(400, fmt::format("{}.value: index {} is a record: write one subindex, or a list of all {} "
                                        "member values",
                                        what, index, record_members(index).size()));
  // Not in the table: the smallest big-endian form, so the device can answer 0x8011/0x8012.
  if (v.is_string()) {
    const std::string s = v.get<std::string>();
    if (s.size() > 232) throw RequestError(400, what + ".value: more than 232 octets (ISDU maximum)");
    return {s.begin(), s.end()};
  }
  return detail::encode_untyped(get_integer(v, what + ".value", std::numeric_limits<int32_t>::min(), 0xFFFFFFFFLL));
}

IsduResult port_isdu_read(Hub::Port& port, uint16_t index, uint8_t subindex) {
  if (port.ds_download_pending) return IsduResult{kIsduServiceTempUnavailable, {}};
  return port.twin.isdu_read(index, subindex);
}

IsduResult port_isdu_write(Hub::Port& port, uint16_t index, uint8_t subindex, std::span<const uint8_t> data) {
  if (port.ds_download_pending) return IsduResult{kIsduServiceTempUnavailable, {}};
  return port.twin.isdu_write(index, subindex, data);
}

Json read_parameter(Hub::Port& port, uint16_t index, uint8_t subindex) {
  const IsduResult r = port_isdu_read(port, index, subindex);
  if (!r.ok()) throw IsduRefused(r.error, iolink_error_name(r.error));
  return parameter_json(index, subindex, r.data);
}

Json write_parameter(Hub::Port& port, uint16_t index, uint8_t subindex, const Json& body) {
  const auto bytes = parameter_bytes(index, subindex, body);
  const IsduResult r = port_isdu_write(port, index, subindex, bytes);
  if (!r.ok()) throw IsduRefused(r.error, iolink_error_name(r.error));
  Json j{{"index", index}, {"subindex", subindex}, {"written", hex_bytes(bytes)}};
  return j;
}

Json faults_json(const Hub::Port& port) {
  const FaultState& f = port.faults;
  return Json{{"link_up", f.link_up},
              {"supply_V", f.supply_V},
              {"external_torque_Nm", f.external_torque_Nm},
              {"flange_blocked", f.flange_blocked},
              {"ambient_C", f.ambient_C},
              {"power_cycles", f.power_cycles},
              {"device_replacements", f.device_replacements},
              {"data_storage", port.ds_backup ? Json{{"backup", true}, {"checksum", port.ds_backup->checksum}}
                                              : Json{{"backup", false}, {"checksum", nullptr}}},
              {"data_storage_error", port.ds_last_error == 0 ? Json(nullptr) : Json(iolink_error_text(port.ds_last_error))}};
}

Json apply_faults(Hub::Port& port, const Json& body) {
  const std::string what = "faults";
  if (!body.is_object() || body.empty()) throw RequestError(400, what + ": expected a JSON object with at least one fault");
  check_keys(body, {"link_up", "supply_V", "external_torque_Nm", "flange_blocked", "ambient_C", "power_cycle",
                    "replace_device"},
             what);
  FaultState f = port.faults;
  constexpr WorldRanges world{}; // a fault sets what a scenario's world could: the same ranges (A-SCN-32)
  if (body.contains("link_up")) f.link_up = get_bool(body["link_up"], what + ".link_up");
  if (body.contains("supply_V")) f.supply_V = get_number(body["supply_V"], what + ".supply_V", world.min_supply_V, world.max_supply_V);
  if (body.contains("external_torque_Nm"))
    f.external_torque_Nm = get_number(body["external_torque_Nm"], what + ".external_torque_Nm", -10.0, 10.0);
  if (body.contains("flange_blocked")) f.flange_blocked = get_bool(body["flange_blocked"], what + ".flange_blocked");
  if (body.contains("ambient_C")) f.ambient_C = get_number(body["ambient_C"], what + ".ambient_C", world.min_ambient_C, world.max_ambient_C);
  const bool cycle = body.contains("power_cycle") && get_bool(body["power_cycle"], what + ".power_cycle");
  const bool replace = body.contains("replace_device") && get_bool(body["replace_device"], what + ".replace_device");
  // All checked: apply.
  Twin& t = port.twin;
  if (f.link_up != port.faults.link_up) t.set_link_up(f.link_up);
  if (f.supply_V != port.faults.supply_V) t.set_supply_voltage(f.supply_V);
  if (f.external_torque_Nm != port.faults.external_torque_Nm) t.set_external_torque(f.external_torque_Nm);
  if (f.flange_blocked != port.faults.flange_blocked) t.set_flange_blocked(f.flange_blocked);
  if (f.ambient_C != port.faults.ambient_C) t.set_ambient_C(f.ambient_C);
  if (cycle) {
    t.power_cycle();
    ++f.power_cycles;
  }
  if (replace) { // manual 8: a new module; the master restores its backup once it is up
    t.replace_device();
    ++f.device_replacements;
    port.ds_download_pending = true;
    ++port.ds_generation; // on disk before the answer: owed also after a kill
  }
  port.faults = f;
  return faults_json(port);
}

Json parse_body(const std::string& body) {
  Json j;
  try {
    j = Json::parse(body);
  } catch (const Json::parse_error& e) {
    // Position only: the parser's own message quotes the input (a token in it
    // would reach MQTT's errors topic, issue 27).
    throw RequestError(400, fmt::format("malformed JSON at byte {}", e.byte));
  } catch (const std::exception&) {
    throw RequestError(400, "malformed JSON");
  }
  if (!j.is_object()) throw RequestError(400, "expected a JSON object");
  return j;
}

} // namespace sreh::serve
