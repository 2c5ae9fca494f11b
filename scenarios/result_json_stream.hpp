// `run --json` with memory flat in run length (issue 12): the records that
// grow with the run (checks, failures, moves) are written to io::Spool
// temporaries as the runner hands them over, and the JSON object is
// assembled at the end by copying them in. The bytes are exactly those of
// to_json(result).dump(indent, ' ', false, replace) on the same run with
// everything kept in memory (tests/scenarios/result_json_stream_test.cpp).
#pragma once
#include <iosfwd>
#include <memory>

#include <nlohmann/json.hpp>

#include "scenarios/runner.hpp"

namespace sreh {

class ResultJsonStream {
 public:
  // indent 2: as `run FILE --json` prints it; -1: compact, on one line (the
  // JSON Lines of `run DIR --json`). Throws std::runtime_error if no
  // temporary file can be created.
  explicit ResultJsonStream(int indent = 2);
  ~ResultJsonStream();
  ResultJsonStream(const ResultJsonStream&) = delete;
  ResultJsonStream& operator=(const ResultJsonStream&) = delete;

  // Sets options' check, failure and move sinks to this stream (which must
  // outlive the run).
  void attach(RunOptions& options);
  // The whole object (without a final newline) for the finished run: its
  // streamed arrays from the spools, everything else from `result`.
  // `extra` members (an object) are added to to_json's, e.g. the file name.
  void write(std::ostream& out, const RunResult& result, const nlohmann::json& extra = nlohmann::json::object());

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace sreh
