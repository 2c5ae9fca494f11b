#include "twin/trace.hpp"

#include <charconv>
#include <ostream>
#include <string>

namespace sreh {
namespace {

// Fixed formatting, locale-independent (std::to_chars): identical runs give
// identical bytes.
void put_fixed(std::string& line, double v, int precision) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v == 0.0 ? 0.0 : v, std::chars_format::fixed, precision);
  line.append(buf, res.ptr);
  line.push_back(',');
}

template <std::size_t N>
void put_hex(std::string& line, const std::array<uint8_t, N>& bytes) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  for (uint8_t b : bytes) {
    line.push_back(kHex[b >> 4]);
    line.push_back(kHex[b & 0xF]);
  }
  line.push_back(',');
}

} // namespace

void write_trace_csv(std::ostream& out, const std::vector<TraceRow>& rows) {
  out << "t_s,state,setpoint_deg,position_deg,tracking_error_deg,velocity_dps,torque_Nm,supply_V,temperature_C,"
         "error_code,warning_code,pd_out_hex,pd_in_hex,led,torque_limit_Nm,external_torque_Nm,iolink_led\n";
  std::string line;
  for (const TraceRow& r : rows) {
    line.clear();
    put_fixed(line, r.t_s, 4);
    line.append(state_name(r.state));
    line.push_back(',');
    put_fixed(line, r.setpoint_deg, 6);
    put_fixed(line, r.position_deg, 6);
    put_fixed(line, r.tracking_error_deg, 6);
    put_fixed(line, r.velocity_dps, 3);
    put_fixed(line, r.torque_Nm, 6);
    put_fixed(line, r.supply_V, 4);
    put_fixed(line, r.temperature_C, 4);
    line.append(std::to_string(r.error_code));
    line.push_back(',');
    line.append(std::to_string(r.warning_code));
    line.push_back(',');
    put_hex(line, r.pd_out);
    put_hex(line, r.pd_in);
    line.append(led_name(r.led));
    line.push_back(',');
    put_fixed(line, r.torque_limit_Nm, 6);
    put_fixed(line, r.external_torque_Nm, 6);
    line.append(iolink_led_name(r.iolink_led));
    line.push_back('\n');
    out << line;
  }
}

} // namespace sreh
