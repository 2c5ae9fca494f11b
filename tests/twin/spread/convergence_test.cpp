// Issue 35 part 4: the physics step changes only numerical error, also
// where a single move's time into a tight window is chaotic. Over 12 cases
// (0 / 15000 g cm^2, 10 / 90 / 180 deg, windows of 3 / 15 counts), with
// the median over 25 targets a few counts apart, between physics steps of
// 0.1 / 0.05 ms and 0.025 ms:
//  - the max tracking error moves by <= 2 % in every case;
//  - the time into a 15-count window moves by <= 2 ms, or 2 % where
//    friction makes the heavy load hunt for 150..250 ms before it holds;
//  - a 3-count window is bimodal (held within ~20 ms, or only after a
//    friction hunt of 100..350 ms at the window's edge), so its median
//    jumps between the modes with the step as with the target: its figures
//    are reported (docs/model-card.md "Convergence"), not bounded here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "device_logic/units.hpp"
#include "twin/twin.hpp"

namespace sreh {
namespace {

// 0 .. 24 wire counts (0.0055 deg each) past the nominal target. The heavy
// load's hunt spreads its time into a 15-count window over ~40 ms, so a
// median of nine draws moved by ~5 ms with the draws alone (measured: 252 /
// 258 ms over two sets of nine at the same step); 25 draws give ~3 ms.
constexpr int kTargets = 25;
constexpr double kNever = std::numeric_limits<double>::infinity(); // not in the window for good

struct Median {
  double in_window_s = 0;
  double max_tracking_error_deg = 0;
};

bool write_u16(Twin& twin, uint16_t index, uint8_t sub, uint16_t value) {
  const uint8_t bytes[2] = {static_cast<uint8_t>(value >> 8), static_cast<uint8_t>(value & 0xFF)};
  return twin.isdu_write(index, sub, bytes).ok();
}

// One move from 0 to `target_deg` + `offset_wire` wire counts (2^16 per
// revolution, manual 2.5) at 3000 deg/s, 100 % / 100 %, load configured,
// window `window_counts` (2^19 per revolution), no waiting time, timeout
// off; then held for 0.4 s so that "in the window for good" is decided.
MoveRecord one_move(double load_gcm2, double target_deg, int offset_wire, int window_counts, double dt_s) {
  TwinConfig c;
  c.load = InertiaLoad{load_gcm2};
  c.physics_dt_s = dt_s;
  c.record_trace = false;
  c.visual_detail = false;
  Twin twin(c);
  EXPECT_TRUE(write_u16(twin, 65, 1, 30000));
  EXPECT_TRUE(write_u16(twin, 65, 4, static_cast<uint16_t>(load_gcm2)));
  EXPECT_TRUE(write_u16(twin, 65, 5, static_cast<uint16_t>(window_counts)));
  EXPECT_TRUE(write_u16(twin, 65, 6, 0));
  const uint8_t timeout_off[1] = {0}; // 65.8 is one octet
  EXPECT_TRUE(twin.isdu_write(65, 8, timeout_off).ok());
  ProcessDataOut pd;
  pd.motor_on = true;
  pd.parameter_set = 1;
  twin.set_pd_out(pd);
  for (int i = 0; i < 10 && !twin.pd_in().ready; ++i) twin.run_cycle();
  EXPECT_TRUE(twin.pd_in().ready);
  pd.target_raw = static_cast<int32_t>(deg_to_wire_counts(target_deg)) + offset_wire;
  pd.move = true;
  twin.set_pd_out(pd);
  for (int i = 0; i < 500 && !twin.pd_in().done && !twin.pd_in().error; ++i) twin.run_cycle();
  for (int i = 0; i < 300; ++i) twin.run_cycle(); // 0.6 s held
  EXPECT_EQ(twin.moves().size(), 1u);
  return twin.moves().empty() ? MoveRecord{} : twin.moves().front();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

Median median_over_targets(double load_gcm2, double target_deg, int window_counts, double dt_s) {
  std::vector<double> in_window, tracking;
  for (int offset = 0; offset < kTargets; ++offset) {
    const MoveRecord m = one_move(load_gcm2, target_deg, offset, window_counts, dt_s);
    EXPECT_TRUE(m.completed()) << load_gcm2 << " g cm^2, " << target_deg << " deg, dt " << dt_s;
    in_window.push_back(m.in_window_s.value_or(kNever));
    tracking.push_back(m.max_tracking_error_deg);
    if (std::getenv("SREH_SPREAD_VERBOSE") != nullptr) {
      std::printf("   target +%d: in window %.2f ms, settling %.2f ms, tracking %.5f deg\n", offset, in_window.back() * 1e3,
                  m.settling_s.value_or(-1) * 1e3, tracking.back());
    }
  }
  return {median(in_window), median(tracking)};
}

struct Case {
  double load_gcm2;
  double angle_deg;
  int window_counts;
};

class Convergence : public ::testing::TestWithParam<Case> {};

TEST_P(Convergence, MediansOverSteps) {
  const Case c = GetParam();
  const Median fine = median_over_targets(c.load_gcm2, c.angle_deg, c.window_counts, 0.025e-3);
  for (double dt : {0.1e-3, 0.05e-3}) {
    const Median m = median_over_targets(c.load_gcm2, c.angle_deg, c.window_counts, dt);
    const std::string what = std::to_string(dt * 1e3) + " ms vs 0.025 ms";
    if (c.window_counts >= 15) {
      if (fine.in_window_s == kNever || m.in_window_s == kNever) {
        EXPECT_EQ(m.in_window_s, fine.in_window_s) << what << ": the window is held for good at one step only";
      } else {
        EXPECT_NEAR(m.in_window_s, fine.in_window_s, std::max(0.002, 0.02 * fine.in_window_s)) << what;
      }
    }
    EXPECT_NEAR(m.max_tracking_error_deg, fine.max_tracking_error_deg, 0.02 * fine.max_tracking_error_deg) << what;
    if (std::getenv("SREH_SPREAD_VERBOSE") != nullptr) {
      std::printf("%g g cm^2 %g deg %d counts: dt %g ms in window %.2f ms (0.025: %.2f), tracking %.5f (%.5f) deg\n",
                  c.load_gcm2, c.angle_deg, c.window_counts, dt * 1e3, m.in_window_s * 1e3, fine.in_window_s * 1e3,
                  m.max_tracking_error_deg, fine.max_tracking_error_deg);
    }
  }
}

std::vector<Case> all_cases() {
  std::vector<Case> out;
  for (double load : {0.0, 15000.0}) {
    for (double angle : {10.0, 90.0, 180.0}) {
      for (int window : {3, 15}) out.push_back({load, angle, window});
    }
  }
  return out;
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  const Case& c = info.param;
  return std::to_string(static_cast<int>(c.load_gcm2)) + "gcm2_" + std::to_string(static_cast<int>(c.angle_deg)) +
         "deg_" + std::to_string(c.window_counts) + "counts";
}

INSTANTIATE_TEST_SUITE_P(Twelve, Convergence, ::testing::ValuesIn(all_cases()), case_name);

} // namespace
} // namespace sreh
