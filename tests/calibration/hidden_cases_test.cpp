// Issue 36's done-when, the hidden-style cases the other calibration tests
// do not cover: a truth the fit never starts from is recorded, the log is
// fitted from the card as `calibrate` does (three starts, the bootstrap),
// and every reported 95 % interval must hold the truth, every constant
// flagged identified be within 10 %, and the fitted card predict a held-out
// move (135 deg on its own parameter set, at 5000 g cm^2, or without a load
// after a plan without one) within 5 % and
// max(5 %, 2 ms). On the plan's moves 0, 1, 2 and 7 (a 2 s log) to keep
// each test's CPU modest (docs/calibration.md "Hidden-style cases"); the
// whole plan's cases at 15000 g cm^2 are in calibration_test.cpp.
#include <cstdio>

#include <gtest/gtest.h>

#include "calibration/fit.hpp"
#include "calibration_rig.hpp"
#include "done_when.hpp"

namespace sreh {
namespace {

using test::kSanitized;

const std::vector<int> kMoves{0, 1, 2, 7};
// The loop-tuning case adds the moves `calibrate --plan` at 15000 g cm^2
// names for the loop constants (move 3, to -120 deg on set 4; move 14, to
// 10 deg on set 7: 19 % and 9 % of the velocity bandwidth's change, 13 %
// and 10 % of the integral ratio's).
const std::vector<int> kLoopMoves{0, 1, 2, 3, 7, 14};

// Friction and drive train 24-35 % off the card, inside the ranges (the
// worked example's hidden module).
ModelCard friction_truth() {
  return test::card_with({{"coulomb_friction", 0.0052},
                          {"viscous_friction", 2.025e-4},
                          {"stribeck_excess", 0.0054},
                          {"torsional_stiffness", 3300},
                          {"torsional_damping", 0.31}});
}

FitCase case_for(const MasterLog& log, const Scenario& plan, double load_gcm2) {
  FitCase c;
  c.log = log;
  c.setup = replay_setup(log, InertiaLoad{load_gcm2}, &plan);
  return c;
}

FitResult fit_and_print(const std::vector<FitCase>& cases, const FitOptions& options) {
  const FitResult fit = fit_model(cases, default_model_card(), options);
  std::printf("rms %.5f deg (start %.5f, floor %.5f), %d iterations, %zu replays, %s\n", fit.rms_residual_deg,
              fit.start_rms_residual_deg, fit.floor_rms_deg, fit.iterations, fit.replays, fit.solver_message.c_str());
  return fit;
}

// Without a load the drive train barely rings: what the log cannot show
// must come back not identified, with a range that holds the truth; the
// held-out move is then one without a load too.
TEST(CalibrationCases, FrictionAndDriveTrainWithoutLoad) {
  if (kSanitized) GTEST_SKIP() << "a fit from three starts with the bootstrap; checked in the Release stage";
  const Scenario plan = test::plan_moves(0, kMoves);
  const ModelCard truth = friction_truth();
  const FitResult fit = fit_and_print({case_for(test::record_log(plan, truth), plan, 0)}, FitOptions{});
  EXPECT_TRUE(fit.adequate) << fit.inadequacy;
  test::expect_recovered(fit, truth, 0.10, 0);
  test::expect_predicts_held_out(fit.card, truth, 0.05, 0);
}

TEST(CalibrationCases, FrictionWithoutLoadWithOneCountOfNoise) {
  if (kSanitized) GTEST_SKIP() << "a fit from three starts with the bootstrap; checked in the Release stage";
  const Scenario plan = test::plan_moves(0, kMoves);
  const ModelCard truth = friction_truth();
  const FitResult fit = fit_and_print({case_for(test::record_log(plan, truth, 36u), plan, 0)}, FitOptions{});
  EXPECT_TRUE(fit.adequate) << fit.inadequacy;
  test::expect_recovered(fit, truth, 0.10, 0);
  test::expect_predicts_held_out(fit.card, truth, 0.05, 0);
}

// The module is no twin: its log recorded at a 4 times finer physics step
// (25 us) is fitted with the twin's own (100 us). The replay is then never
// bit-exact, as with a real module.
TEST(CalibrationCases, TruthRecordedAtAFinerPhysicsStep) {
  if (kSanitized) GTEST_SKIP() << "a fit from three starts with the bootstrap; checked in the Release stage";
  constexpr double kLoad_gcm2 = 15000;
  const Scenario plan = test::plan_moves(kLoad_gcm2, kMoves);
  Scenario finer = plan;
  finer.world.physics_dt_s = plan.world.physics_dt_s / 4;
  const ModelCard truth = friction_truth();
  const FitResult fit = fit_and_print({case_for(test::record_log(finer, truth), plan, kLoad_gcm2)}, FitOptions{});
  EXPECT_TRUE(fit.adequate) << fit.inadequacy;
  test::expect_recovered(fit, truth, 0.10, 0);
  test::expect_predicts_held_out(fit.card, truth, 0.05);
}

// Loop tuning from logs at two configured loads (issue 36: at one load the
// bandwidth and the ratios trade off, correlations 0.95-0.98), of the
// moves that show the loop constants (kLoopMoves).
TEST(CalibrationCases, LoopTuningFromTwoLoads) {
  if (kSanitized) GTEST_SKIP() << "a fit from three starts with the bootstrap; checked in the Release stage";
  const ModelCard truth = test::card_with({{"velocity_bandwidth", 1060},  // +6 %
                                           {"position_ratio", 0.27},      // +8 %
                                           {"integral_ratio", 0.36}});    // +20 %
  std::vector<FitCase> cases;
  for (const double load : {0.0, 15000.0}) {
    const Scenario plan = test::plan_moves(load, kLoopMoves);
    cases.push_back(case_for(test::record_log(plan, truth), plan, load));
    cases.back().log.path = load == 0 ? "no_load.csv" : "heavy.csv";
  }
  FitOptions options;
  options.names = {"velocity_bandwidth", "position_ratio", "integral_ratio"};
  const FitResult fit = fit_and_print(cases, options);
  EXPECT_TRUE(fit.adequate) << fit.inadequacy;
  test::expect_recovered(fit, truth, 0.10, 1); // the bandwidth (+-3 %, docs/calibration.md)
  // Issue 36's 5 % and max(5 %, 2 ms) at 5000 g cm^2, between the two
  // loads. The time into the window is the end of a stick-slip creep back
  // after the overshoot, set by the integral action: on moves 0, 1, 2, 7
  // alone the integral ratio came +4 % and the time 2.6 ms (5.4 %) late;
  // with moves 3 and 14 -0.9 ms. It is a rough function of the loop
  // constants (docs/calibration.md "Loop tuning: the held-out move's time
  // into the window").
  test::expect_predicts_held_out(fit.card, truth, 0.05);
}

// A module carrying 5 % more than the stated 5000 g cm^2 (issue 36 point
// 2): the default fit must not pass it off as a module that fits: the log
// is not explained, or a constant ends at its bound, both reported.
TEST(CalibrationCases, AFivePercentLoadErrorIsFlagged) {
  if (kSanitized) GTEST_SKIP() << "a fit from three starts with the bootstrap; checked in the Release stage";
  constexpr double kStated_gcm2 = 5000;
  const Scenario plan = test::plan_moves(kStated_gcm2, kMoves);
  Scenario heavier = plan; // the PLC's sets still configured for the stated load
  heavier.world.load = InertiaLoad{1.05 * kStated_gcm2};
  const FitResult fit = fit_and_print({case_for(test::record_log(heavier, default_model_card()), plan, kStated_gcm2)},
                                      FitOptions{});
  bool at_bound = false;
  for (const FittedConstant& f : fit.constants) at_bound = at_bound || f.at_bound;
  std::printf("adequate %d, a constant at its bound %d: %s\n", fit.adequate, at_bound, fit.inadequacy.c_str());
  EXPECT_TRUE(!fit.adequate || at_bound);
  // Whatever it says, its intervals still hold the module's constants (the card's).
  test::expect_recovered(fit, default_model_card(), 0.10, 0);
}

// The same 5 % load error with the load fitted too (`--fit load`: the
// default constants and the load, A-CAL-14): the load is recovered, its
// interval holds the 5250 g cm^2 carried and excludes the 5000 stated, the
// fit explains the log, and the fitted card with the fitted load predicts
// the held-out move (on a set configured for the stated load, as the PLC's
// are).
TEST(CalibrationCases, AFivePercentLoadErrorIsRecoveredWithFitLoad) {
  if (kSanitized) GTEST_SKIP() << "a fit from three starts with the bootstrap; checked in the Release stage";
  constexpr double kStated_gcm2 = 5000;
  constexpr double kCarried_gcm2 = 5250;
  const Scenario plan = test::plan_moves(kStated_gcm2, kMoves);
  Scenario heavier = plan;
  heavier.world.load = InertiaLoad{kCarried_gcm2};
  FitOptions options;
  options.names = {"load"};
  const FitResult fit = fit_and_print({case_for(test::record_log(heavier, default_model_card()), plan, kStated_gcm2)},
                                      options);
  for (const std::string& note : fit.notes) std::printf("note: %s\n", note.c_str());
  EXPECT_TRUE(fit.adequate) << fit.inadequacy;
  ASSERT_EQ(fit.constants.size(), default_fit_names().size() + 1);
  const FittedConstant& load = fit.constants.back();
  ASSERT_TRUE(load.load);
  EXPECT_EQ(load.name, "load_inertia");
  EXPECT_NEAR(load.start, kStated_gcm2, 0.5); // as MuJoCo computes it
  EXPECT_TRUE(load.identified) << load.note;
  EXPECT_NEAR(load.value, kCarried_gcm2, 0.02 * kCarried_gcm2);
  EXPECT_GT(load.ci95_lo, kStated_gcm2); // the stated load is excluded: the error is named
  ASSERT_EQ(fit.load_scale.size(), 1u);
  EXPECT_NEAR(fit.load_scale[0] * load.start, load.value, 1e-9 * load.value);
  bool named = false;
  for (const std::string& note : fit.notes) named = named || note.starts_with("the module carries 52");
  EXPECT_TRUE(named) << "no note naming the carried load";
  test::expect_recovered(fit, default_model_card(), 0.10, 0, kCarried_gcm2);
  test::expect_predicts_held_out(fit.card, default_model_card(), 0.05, kCarried_gcm2, load.value, kStated_gcm2);
}

} // namespace
} // namespace sreh
