#include "tools/progress.hpp"

#include <cstdio>

namespace sreh::tools {
namespace {
constexpr auto kQuiet = std::chrono::seconds(2);          // nothing for shorter work
constexpr auto kLogEvery = std::chrono::seconds(5);       // a log line at most this often
constexpr auto kRedrawEvery = std::chrono::milliseconds(200);
} // namespace

Progress::~Progress() {
  end_phase();
  if (redrawn_) std::fprintf(stderr, "\r%60s\r", "");
}

void Progress::phase(const std::string& name) {
  end_phase();
  phase_ = name;
  start_ = last_ = Clock::now();
  shown_ = false;
}

void Progress::update(double fraction, double simulated_s) {
  if (quiet_ || phase_.empty() || (++calls_ % 16) != 0) return; // the clock is read every 16th call only
  const auto now = Clock::now();
  if (now - start_ < kQuiet) return;
  if (shown_ && now - last_ < (terminal_ ? kRedrawEvery : kLogEvery)) return;
  last_ = now;
  print(fraction, simulated_s, false);
}

void Progress::update_count(uint64_t done, const std::string& unit) {
  count_unit_ = unit;
  count_ = done;
  if (quiet_ || phase_.empty()) return;
  const auto now = Clock::now();
  if (now - start_ < kQuiet) return;
  if (shown_ && now - last_ < (terminal_ ? kRedrawEvery : kLogEvery)) return;
  last_ = now;
  print(-1.0, 0, false);
}

void Progress::end_phase() {
  if (!phase_.empty() && shown_ && !quiet_) print(count_unit_.empty() ? 1.0 : -1.0, 0, true);
  phase_.clear();
  count_unit_.clear();
}

void Progress::print(double fraction, double simulated_s, bool final_line) {
  const double elapsed_s = std::chrono::duration<double>(Clock::now() - start_).count();
  char what[96];
  if (!count_unit_.empty()) {
    std::snprintf(what, sizeof what, "%llu %s (%.0f s)", static_cast<unsigned long long>(count_), count_unit_.c_str(), elapsed_s);
  } else if (fraction >= 0) {
    const double eta_s = fraction > 0.01 && !final_line ? elapsed_s * (1.0 - fraction) / fraction : -1.0;
    if (eta_s >= 0) std::snprintf(what, sizeof what, "%3.0f %% (%.0f s, about %.0f s to go)", 100 * fraction, elapsed_s, eta_s);
    else std::snprintf(what, sizeof what, "%3.0f %% (%.0f s)", 100 * fraction, elapsed_s);
  } else {
    std::snprintf(what, sizeof what, "%.1f s simulated (%.0f s)", simulated_s, elapsed_s);
  }
  if (terminal_) {
    std::fprintf(stderr, "\r%s: %s%s", phase_.c_str(), what, final_line ? "\n" : "   ");
    redrawn_ = !final_line;
  } else {
    std::fprintf(stderr, "sreh-twin: %s: %s\n", phase_.c_str(), what);
  }
  std::fflush(stderr);
  shown_ = true;
}

} // namespace sreh::tools
