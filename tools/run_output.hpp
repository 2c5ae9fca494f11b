// What `sreh-twin run` prints for a scenario: the text summary, or with
// --json one object (interfaces.md). Streamed (issue 12): the checks,
// failures and moves of a long run are not held in memory but handed to
// io::Spool temporaries by the runner and copied out at the end; the bytes
// are those of the in-memory path (scenarios/result_json_stream.hpp).
#pragma once
#include <iosfwd>
#include <memory>
#include <optional>

#include "io/spool.hpp"
#include "scenarios/result_json_stream.hpp"
#include "scenarios/runner.hpp"

namespace sreh::tools {

class RunOutput {
 public:
  // Throws std::runtime_error if a temporary file cannot be created.
  // `json_line`: --json as one compact line (`run DIR --json`, JSON Lines).
  explicit RunOutput(bool json, bool json_line = false);
  void attach(RunOptions& options); // before the run; must outlive it
  // `run FILE`: the summary, or the --json object; `wall_s` the run's wall
  // time (JSON: wall_s and real_time_factor = simulated / wall, last).
  void print(std::ostream& out, const RunResult& result, double wall_s);
  // `run DIR`, per file: "PASS  FILE  NAME  (S s simulated, W s)" and the
  // failures under it, or --json: the object of `run FILE --json` with
  // "file", on one line.
  void print_file_line(std::ostream& out, const RunResult& result, const std::string& file, double wall_s);

 private:
  void print_failures(std::ostream& out);
  bool json_;
  bool json_line_;
  std::optional<ResultJsonStream> json_stream_;
  std::optional<io::Spool> failure_lines_; // text: "  <failure>\n" each
};

} // namespace sreh::tools
