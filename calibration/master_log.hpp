// The master log (issue 26): what an IO-Link master sees of the module, one
// row per master cycle: `t_s,pd_out,pd_in[,temperature_C]`, process data as
// hex (6 and 7 octets: 12 and 14 digits, manual 2.2 / 2.3), the temperature
// (index 112, manual 6.4) where the PLC polled it, blank otherwise.
// docs/calibration.md "The master log" gives the format for other masters.
#pragma once
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "device_logic/process_data.hpp"

namespace sreh {

// A log that cannot be used (exit 2): "FILE:LINE: what is wrong".
class CalibrationInputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct MasterLogRow {
  double t_s = 0;
  PdOutFrame pd_out{};
  PdInFrame pd_in{};
  std::optional<double> temperature_C;
  int line = 0; // in the file, 1-based (the header is line 1)
};

struct MasterLog {
  std::string path;
  bool has_temperature = false; // the column is there (it may still be blank everywhere)
  std::vector<MasterLogRow> rows;
};

// Reads and checks a log: header, hex widths, numbers, time strictly
// increasing. Throws CalibrationInputError naming path:line.
MasterLog read_master_log(const std::string& path);

// Writing, in the same format (run --master-log streams it row by row).
void write_master_log_header(std::ostream& out);
void write_master_log_row(std::ostream& out, double t_s, const PdOutFrame& pd_out, const PdInFrame& pd_in,
                          std::optional<double> temperature_C);

// The logged position in degrees: the wire's counts (2^16 per revolution,
// manual 2.5) plus half a count, since the device floors its 2^19 encoder
// counts to the wire's (device_logic/position_frame.hpp): the unbiased
// estimate of the position the module had.
double logged_position_deg(const PdInFrame& pd_in);

} // namespace sreh
