// `calibrate --plan`'s table of which move shows which constant (issue 36:
// "prints which segment identifies which constant"), measured on the twin.
#include "calibration/plan_sensitivity.hpp"

#include <gtest/gtest.h>

#include <numeric>

#include "tests/calibration/calibration_rig.hpp"

namespace sreh {
namespace {

TEST(PlanSensitivity, SharesEachChangeOverThePlansEighteenMoves) {
  const Scenario plan = test::plan_scenario(test::kPlanLoad_gcm2);
  const PlanSensitivity s = plan_sensitivity(plan, default_model_card(), {"velocity_bandwidth", "coulomb_friction"}, 2);
  ASSERT_EQ(s.moves.size(), 18u); // the plan's moves, found by their Move edges (manual 2.2)
  EXPECT_EQ(s.moves[0].parameter_set, 1);
  EXPECT_NEAR(s.moves[0].target_deg, 90, 0.01);
  EXPECT_EQ(s.moves[7].parameter_set, 0); // the 30 deg/s crawl
  EXPECT_NEAR(s.moves[7].target_deg, 20, 0.01);
  for (std::size_t m = 1; m < s.moves.size(); ++m) EXPECT_GE(s.moves[m].t0_s, s.moves[m - 1].t1_s);
  ASSERT_EQ(s.constants.size(), 2u);
  for (const ConstantSensitivity& c : s.constants) {
    ASSERT_EQ(c.share.size(), s.moves.size());
    const double total = std::accumulate(c.share.begin(), c.share.end(), 0.0);
    EXPECT_LE(total, 1 + 1e-9) << c.name;
    EXPECT_GT(total, 0.9) << c.name; // before the first move the module stands at its start
    EXPECT_NEAR(c.step_relative, 0.10, 1e-12) << c.name;
  }
  // The loop's bandwidth shades every move: it shows well above the jitter.
  EXPECT_TRUE(s.constants[0].shows);
  EXPECT_GT(s.constants[0].rms_change_counts, 2 * s.jitter.rms_change_counts);
}

// The mechanism that bounds what a position log can tell (docs/calibration.md
// "Which moves show which constant"): a quantised encoder in the loop turns a
// change of 0.1 % into a whole count flipped somewhere, which carries on.
TEST(PlanSensitivity, ATenthOfAPercentFlipsACount) {
  const Scenario plan = test::plan_scenario(test::kPlanLoad_gcm2);
  const PlanSensitivity s = plan_sensitivity(plan, default_model_card(), {"coulomb_friction"}, 2);
  EXPECT_EQ(s.jitter.name, "coulomb_friction");
  EXPECT_NEAR(s.jitter.step_relative, 0.001, 1e-12);
  EXPECT_GE(s.jitter.peak_change_counts, 1.0);
  EXPECT_GT(s.jitter.rms_change_counts, 0.0);
}

TEST(PlanSensitivity, AStepThatLeavesTheRangeGoesTheOtherWay) {
  // torque_constant's range reaches only ~3 % above the card's value and
  // ~3 % below it: the step stays inside, to the farther bound.
  const ModelCard& card = default_model_card();
  const ModelConstant* kt = card.find("torque_constant");
  ASSERT_NE(kt, nullptr);
  ASSERT_GT(kt->value * 1.1, kt->range_hi);
  Scenario plan = test::plan_scenario(0);
  plan.steps.resize(3 + 2 * 5); // motor on, wait, hold, the first two moves
  const PlanSensitivity s = plan_sensitivity(plan, card, {"torque_constant"}, 2);
  ASSERT_EQ(s.moves.size(), 2u);
  const double moved = kt->value * (1 + s.constants[0].step_relative);
  EXPECT_GE(moved, kt->range_lo - 1e-12);
  EXPECT_LE(moved, kt->range_hi + 1e-12);
  EXPECT_TRUE(std::abs(moved - kt->range_lo) < 1e-9 || std::abs(moved - kt->range_hi) < 1e-9);
}

} // namespace
} // namespace sreh
