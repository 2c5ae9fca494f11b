#include "calibration/master_log.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <ostream>

#include <fmt/format.h>

#include "device_logic/units.hpp"

namespace sreh {
namespace {

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) {
  throw CalibrationInputError(fmt::format("{}:{}: {}", path, line, what));
}

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> fields;
  std::string::size_type start = 0;
  while (true) {
    const auto comma = text.find(',', start);
    fields.push_back(text.substr(start, comma - start));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

template <std::size_t N>
std::array<uint8_t, N> parse_hex(const std::string& path, int line, const char* column, const std::string& text) {
  if (text.size() != 2 * N) {
    fail(path, line, fmt::format("{} \"{}\": expected {} hex digits ({} octets)", column, text, 2 * N, N));
  }
  std::array<uint8_t, N> bytes{};
  for (std::size_t i = 0; i < N; ++i) {
    const char* first = text.data() + 2 * i;
    const auto res = std::from_chars(first, first + 2, bytes[i], 16);
    if (res.ec != std::errc() || res.ptr != first + 2) {
      fail(path, line, fmt::format("{} \"{}\": not hexadecimal", column, text));
    }
  }
  return bytes;
}

double parse_number(const std::string& path, int line, const char* column, const std::string& text) {
  double v = 0;
  const auto res = std::from_chars(text.data(), text.data() + text.size(), v);
  if (res.ec != std::errc() || res.ptr != text.data() + text.size() || !std::isfinite(v)) {
    fail(path, line, fmt::format("{} \"{}\": not a number", column, text));
  }
  return v;
}

} // namespace

MasterLog read_master_log(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw CalibrationInputError(fmt::format("{}: cannot be read", path));
  MasterLog log;
  log.path = path;
  std::string text;
  int line = 0;
  if (!std::getline(in, text)) fail(path, 1, "empty; expected the header t_s,pd_out,pd_in[,temperature_C]");
  ++line;
  const std::string header = trim(text);
  if (header == "t_s,pd_out,pd_in,temperature_C") log.has_temperature = true;
  else if (header != "t_s,pd_out,pd_in") {
    fail(path, line, fmt::format("header \"{}\": expected t_s,pd_out,pd_in or t_s,pd_out,pd_in,temperature_C", header));
  }
  const std::size_t columns = log.has_temperature ? 4 : 3;
  while (std::getline(in, text)) {
    ++line;
    if (trim(text).empty()) continue;
    std::vector<std::string> f = split_commas(text);
    if (f.size() != columns) fail(path, line, fmt::format("{} columns, the header has {}", f.size(), columns));
    for (auto& s : f) s = trim(s);
    MasterLogRow row;
    row.line = line;
    row.t_s = parse_number(path, line, "t_s", f[0]);
    row.pd_out = parse_hex<kPdOutBytes>(path, line, "pd_out", f[1]);
    row.pd_in = parse_hex<kPdInBytes>(path, line, "pd_in", f[2]);
    if (log.has_temperature && !f[3].empty()) row.temperature_C = parse_number(path, line, "temperature_C", f[3]);
    if (!log.rows.empty() && row.t_s <= log.rows.back().t_s) {
      fail(path, line, fmt::format("t_s {} does not increase (line {}: {})", f[0], log.rows.back().line,
                                   log.rows.back().t_s));
    }
    log.rows.push_back(row);
  }
  if (log.rows.size() < 2) fail(path, line, "fewer than two rows of process data");
  return log;
}

void write_master_log_header(std::ostream& out) { out << "t_s,pd_out,pd_in,temperature_C\n"; }

void write_master_log_row(std::ostream& out, double t_s, const PdOutFrame& pd_out, const PdInFrame& pd_in,
                          std::optional<double> temperature_C) {
  std::string line = fmt::format("{:.6f},", t_s);
  for (uint8_t b : pd_out) line += fmt::format("{:02x}", b);
  line += ',';
  for (uint8_t b : pd_in) line += fmt::format("{:02x}", b);
  line += ',';
  if (temperature_C) line += fmt::format("{:.1f}", *temperature_C);
  line += '\n';
  out << line;
}

double logged_position_deg(const PdInFrame& pd_in) {
  const ProcessDataIn in = decode_in(pd_in);
  return (static_cast<double>(in.position_raw) + 0.5) * (360.0 / static_cast<double>(kWireCountsPerRev)); // manual 2.5
}

} // namespace sreh
