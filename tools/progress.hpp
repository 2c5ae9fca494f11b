// Progress on stderr for work that takes a while (issue 29): on a terminal a
// line redrawn in place (at most every 0.2 s); otherwise, so that a CI log
// does not look hung, a line with the phase, percent and ETA once the phase
// has run 2 s, then at most every 5 s, and its 100 % at the end. Nothing
// for work under 2 s, nothing with --quiet. Wall time is the CLI's business:
// the simulation never reads it.
#pragma once
#include <chrono>
#include <cstdint>
#include <string>

namespace sreh::tools {

class Progress {
 public:
  Progress(bool terminal, bool quiet) : terminal_(terminal), quiet_(quiet) {}
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Starts a phase ("simulating", "rendering the video"); ends the one before.
  void phase(const std::string& name);
  // `fraction` of the phase done (0..1), or < 0 when unknown: then the
  // simulated time stands for it ("12.5 s simulated").
  void update(double fraction, double simulated_s = 0);
  // Work whose size is not known ahead: how many `unit` done so far
  // ("14 simulations (3 s)").
  void update_count(uint64_t done, const std::string& unit);
  void end_phase(); // prints the 100 % line if the phase printed any

 private:
  using Clock = std::chrono::steady_clock;
  void print(double fraction, double simulated_s, bool final_line);
  void print_line(const std::string& what, bool final_line);
  std::string count_unit_; // set: the phase counts, update_count
  uint64_t count_ = 0;
  bool terminal_;
  bool quiet_;
  std::string phase_;
  Clock::time_point start_{}, last_{};
  bool shown_ = false;
  bool redrawn_ = false; // a terminal line is on screen
  unsigned calls_ = 0;
};

} // namespace sreh::tools
