// Where a value came from in an input file, and the error that names it:
// shared by every file the project reads (scenarios, cycles, loads, ports),
// so a message always starts "FILE:LINE:COL:".
#pragma once
#include <stdexcept>
#include <string>

namespace sreh {

// A position in an input file; line and column are 1-based (0: unknown).
struct SourceLoc {
  std::string file;
  int line = 0;
  int column = 0;
  std::string str() const; // "FILE:LINE:COL" (or just FILE when unknown)
};

// Bad input (exit code 2). what() is "FILE:LINE:COL: what is wrong".
class ScenarioError : public std::runtime_error {
 public:
  ScenarioError(const SourceLoc& loc, const std::string& message);
  const SourceLoc& where() const { return loc_; }
  const std::string& message() const { return message_; } // without the location
 private:
  SourceLoc loc_;
  std::string message_;
};

} // namespace sreh
