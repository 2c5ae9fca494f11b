// What `sreh-twin run` prints for a scenario: the text summary, or with
// --json one object (interfaces.md). Streamed (issue 12): the checks,
// failures and moves of a long run are not held in memory but handed to
// io::Spool temporaries by the runner and copied out at the end; the bytes
// are those of the in-memory path. `in_memory` keeps them in the RunResult
// instead (--report draws them).
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
  RunOutput(bool json, bool in_memory);
  void attach(RunOptions& options); // before the run; must outlive it
  void print(std::ostream& out, const RunResult& result);

 private:
  bool json_;
  bool in_memory_;
  std::optional<ResultJsonStream> json_stream_;
  std::optional<io::Spool> failure_lines_; // text: "  <failure>\n" each
};

} // namespace sreh::tools
