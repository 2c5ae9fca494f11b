// /v1/stats shows real figures (issue 27): cycles later than 100 ms count
// with their lateness, not capped at 99999 us.
#include <gtest/gtest.h>

#include <thread>

#include "serve/hub.hpp"

namespace sreh::serve {
namespace {

TEST(HubStats, JitterBeyond100msIsNotCapped) {
  HubOptions o;
  o.cycle_s = 0.002;
  Hub hub(std::vector<TwinConfig>(1), o);
  hub.start();
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  hub.with_port(1, [](Hub::Port&) { std::this_thread::sleep_for(std::chrono::milliseconds(250)); }); // a stall
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  hub.stop();
  const PacingStats s = hub.stats();
  EXPECT_GT(s.jitter_max_us, 200000);
  EXPECT_GT(s.jitter_p99_us, 100000) << "p99 over " << s.cycles << " cycles";
  EXPECT_GT(s.late_cycles, 50u);
}

} // namespace
} // namespace sreh::serve
