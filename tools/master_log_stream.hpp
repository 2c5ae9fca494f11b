// `run --master-log FILE.csv` (issue 26): the run as an IO-Link master
// records it (calibration/master_log.hpp), streamed row by row into the
// file's temporary and committed when the run finished.
#pragma once
#include <optional>
#include <string>

#include "io/atomic_file.hpp"
#include "scenarios/runner.hpp"

namespace sreh::tools {

class MasterLogStream {
 public:
  explicit MasterLogStream(const std::string& path);
  // Chains itself into the run's trace sink and ISDU-read hook.
  void attach(RunOptions& options);
  void commit() { file_.commit(); }

 private:
  void row(const TraceRow& r);
  void isdu_read(uint16_t index, uint8_t subindex, const IsduResult& result);

  io::AtomicFile file_;
  std::optional<double> polled_temperature_C_; // read since the last row
};

} // namespace sreh::tools
