// `run FILE|DIR --junit FILE` (issue 29): the runs as JUnit XML, the format
// CI servers (GitLab, Jenkins, GitHub) read. One <testcase> per scenario
// (classname = its folder, name = its file's stem, time = wall time), a
// <failure> with the failing steps (line and message), <system-out> with the
// checks; bad input found while running is an <error>. Written whole at the
// end (io::write_file_atomic). Schema: tests/tools/junit.xsd.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "scenarios/runner.hpp"

namespace sreh::tools {

class JunitReport {
 public:
  // Starts the next test case; `chain` then adds the report's sinks to the
  // run's options, after the ones already there (they still get everything).
  void begin_case(const std::string& file, const std::string& scenario_name);
  void chain(RunOptions& options);
  void end_case(const RunResult& result, double wall_s);
  void end_case_with_error(const std::string& message); // bad input found only while running
  void write(const std::string& path) const; // throws std::runtime_error on an I/O failure

 private:
  struct Case {
    std::string classname, name, file, scenario_name;
    double wall_s = 0;
    bool error = false;
    std::vector<std::string> failures;
    std::string checks; // "PASS  step 4 (line 12) ..." lines, capped
    std::size_t check_lines = 0;
    std::size_t checks_left_out = 0;
  };
  std::vector<Case> cases_;
};

} // namespace sreh::tools
