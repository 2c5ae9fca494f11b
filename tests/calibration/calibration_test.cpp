// Issue 26 done-when: a log recorded from a "module" whose friction,
// stiffness and damping differ from the card by 30-40 % is calibrated
// without knowing them; the constants come back and the fitted twin
// predicts a held-out move.
#include <cmath>

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "calibration/fit.hpp"
#include "calibration/fit_output.hpp"
#include "calibration_rig.hpp"
#include "done_when.hpp"

namespace sreh {
namespace {

using test::kPlanLoad_gcm2;
using test::kSanitized;

// The hidden module (examples/calibration/hidden_module.yaml): five
// friction, stiffness and damping constants moved by 24-35 % inside their
// ranges (issue 35: the values follow the card's drive layout).
ModelCard hidden_card() {
  return test::card_with({{"coulomb_friction", 0.0052},      // -35 %
                          {"viscous_friction", 2.025e-4},    // +35 %
                          {"stribeck_excess", 0.0054},       // +35 %
                          {"torsional_stiffness", 3300},     // +32 %
                          {"torsional_damping", 0.31}});     // +24 % (the range's top)
}

// The plan with the heaviest load the module takes (manual 3.5.6): the
// flange's ringing after fast stops shows stiffness and damping best.
std::vector<FitCase> cases_for(const MasterLog& log, const Scenario& plan) {
  FitCase c;
  c.log = log;
  c.setup = replay_setup(log, InertiaLoad{kPlanLoad_gcm2}, &plan);
  return {c};
}

TEST(Replay, TheRecordingModelGivesTheLogBackBitForBit) {
  const Scenario plan = test::plan_scenario(kPlanLoad_gcm2);
  const ModelCard hidden = hidden_card();
  const MasterLog log = test::record_log(plan, hidden);
  const auto cases = cases_for(log, plan);
  const ReplayTrack track = replay(cases[0].setup, hidden.module_model(), log);
  for (std::size_t k = 0; k < log.rows.size(); ++k) ASSERT_EQ(track.pd_in[k], log.rows[k].pd_in) << "row " << k;
}

using test::expect_predicts_held_out;
using test::expect_recovered;

// The fit itself, cheaply, everywhere: one constant from the first moves of the plan.
TEST(Calibration, OneConstantFromAShortLog) {
  Scenario plan = test::plan_scenario(kPlanLoad_gcm2);
  plan.steps.resize(3 + 4 * 5); // motor on, wait, hold, then the first four moves (5 steps each)
  const ModelCard hidden = test::card_with({{"coulomb_friction", 0.0052}});
  const auto cases = cases_for(test::record_log(plan, hidden), plan);
  FitOptions options;
  options.names = {"coulomb_friction"};
  options.starts = 1;          // cheap: the solve itself
  options.bootstrap = 0;
  const FitResult fit = fit_model(cases, default_model_card(), options);
  std::printf("%d iterations, %zu replays, %s\n", fit.iterations, fit.replays, fit.solver_message.c_str());
  ASSERT_EQ(fit.constants.size(), 1u);
  const FittedConstant& c = fit.constants[0];
  EXPECT_NEAR(c.value, 0.0052, 0.10 * 0.0052) << fit.solver_message;
  EXPECT_LE(c.ci95_lo, c.value);
  EXPECT_GE(c.ci95_hi, c.value);
  EXPECT_LT(fit.rms_residual_deg, fit.start_rms_residual_deg);
}

TEST(Calibration, HiddenConstantsComeBackAndPredictAHeldOutMove) {
  if (kSanitized) GTEST_SKIP() << "20 s of CPU in Release; checked in the Release stage";
  const Scenario plan = test::plan_scenario(kPlanLoad_gcm2);
  const ModelCard hidden = hidden_card();
  const auto cases = cases_for(test::record_log(plan, hidden), plan);
  FitOptions options;
  const FitResult fit = fit_model(cases, default_model_card(), options);
  std::printf("rms %.5f deg (start %.5f), %d iterations, %zu replays, %s\n", fit.rms_residual_deg,
              fit.start_rms_residual_deg, fit.iterations, fit.replays, fit.solver_message.c_str());
  EXPECT_TRUE(fit.converged);
  EXPECT_TRUE(fit.adequate) << fit.inadequacy;
  // The bootstrap identifies Coulomb friction here (+-9 %, 1.2 % off;
  // docs/calibration.md): at least one, so an uninformative fit fails.
  expect_recovered(fit, hidden, 0.10, 1);
  expect_predicts_held_out(fit.card, hidden, 0.05);

  // FIT.yaml is a model file --model reads: the fitted values come back
  // with the card's range, an identified one with its interval (issue 36).
  const std::string path = testing::TempDir() + "/fit.yaml";
  std::ofstream(path) << fit_model_yaml(fit, default_model_card(), {"recorded.csv"}, "2026-11-26");
  const ModelCard read = apply_model_file(default_model_card(), path);
  for (const FittedConstant& f : fit.constants) {
    const ModelConstant* c = read.find(f.name);
    EXPECT_EQ(c->value, f.value) << f.name;
    EXPECT_NE(c->source.find("calibrated from recorded.csv on 2026-11-26"), std::string::npos);
    EXPECT_EQ(c->range_lo, default_model_card().find(f.name)->range_lo);
    EXPECT_EQ(c->has_interval, f.identified) << f.name;
    if (f.identified) {
      EXPECT_EQ(c->interval_lo, std::max(f.ci95_lo, default_model_card().find(f.name)->range_lo));
    }
  }
}

// Issue 26: thermal constants from the polled temperatures (A-CAL-9). The
// plan's 9 s, mostly holds, do not heat the card's winding (3 K/W to the
// housing) by even a sensor step, so the log here is the heating one of
// the rig: 18 fast long moves with the temperature read after each and the
// twin's thermal clock 20 times fast (2 minutes of heating, 25.5 to 29
// degC), what a real module shows in a log of that length.
TEST(Calibration, ThermalConstantsFromThePolledTemperature) {
  if (kSanitized) GTEST_SKIP() << "three starts and the bootstrap, minutes instrumented; checked in the Release stage";
  const Scenario plan = test::heating_scenario(kPlanLoad_gcm2, 20);
  const ModelCard hidden = test::card_with({{"winding_heat_capacity", 13.44},            // +12 %
                                            {"winding_to_housing_resistance", 3.36}});  // +12 %
  const auto cases = cases_for(test::record_log(plan, hidden), plan);
  std::size_t polled = 0;
  for (const MasterLogRow& row : cases[0].log.rows) polled += row.temperature_C ? 1 : 0;
  ASSERT_EQ(polled, 18u); // one read after every move
  FitOptions options;
  options.names = {"winding_heat_capacity", "winding_to_housing_resistance"};
  const FitResult fit = fit_model(cases, default_model_card(), options);
  std::printf("rms %.5f deg, %.3f degC over %zu polls, %d iterations, %zu replays, %s\n", fit.rms_residual_deg,
              fit.rms_temperature_residual_C, fit.temperature_residuals, fit.iterations, fit.replays,
              fit.solver_message.c_str());
  EXPECT_TRUE(fit.converged);
  EXPECT_EQ(fit.temperature_residuals, 18u);
  EXPECT_LT(fit.rms_temperature_residual_C, 0.25); // within the sensor's half step
  for (const FittedConstant& f : fit.constants) {
    const double truth = hidden.find(f.name)->value;
    std::printf("%-30s truth %-6g start %-6g fit %-8g ci95 [%g, %g]\n", f.name.c_str(), truth, f.start, f.value,
                f.ci95_lo, f.ci95_hi);
    EXPECT_NEAR(f.value, truth, 0.05 * truth) << f.name;
    EXPECT_LE(f.ci95_lo, truth) << f.name;
    EXPECT_GE(f.ci95_hi, truth) << f.name;
  }
}

// Issue 26: "thermal ones when a temperature column is present": the
// winding's two constants join the default fit when a log heats by
// kThermalFitSpan_C over at least the winding's time constant (36 s on
// the card); the 9 s plan at the real thermal clock is far shorter, so they
// stay out with a note saying why (A-CAL-9).
TEST(Calibration, DefaultFitAddsTheWindingWhenTheLogHeatsUp) {
  Scenario plan = test::plan_scenario(kPlanLoad_gcm2);
  const DefaultFit flat = default_fit(cases_for(test::record_log(plan, default_model_card()), plan), default_model_card());
  EXPECT_EQ(flat.names, default_fit_names());
  EXPECT_NE(flat.note.find("thermal constants not fitted: the longest log lasts 9 s of the winding's 36 s"),
            std::string::npos)
      << flat.note;

  // Long enough (3 minutes on a clock 20 times fast), but the plan's holds
  // heat by 1 degC only.
  plan.world.thermal.time_scale = 20;
  const DefaultFit lukewarm = default_fit(cases_for(test::record_log(plan, default_model_card()), plan), default_model_card());
  EXPECT_EQ(lukewarm.names, default_fit_names());
  EXPECT_NE(lukewarm.note.find("the polled temperature spans 1.0 degC, a fit needs 2 degC"), std::string::npos)
      << lukewarm.note;

  const Scenario heating = test::heating_scenario(kPlanLoad_gcm2, 20); // 2 minutes of fast moves: 3.5 degC
  const DefaultFit heated =
      default_fit(cases_for(test::record_log(heating, default_model_card()), heating), default_model_card());
  std::vector<std::string> want = default_fit_names();
  want.insert(want.end(), {"winding_heat_capacity", "winding_to_housing_resistance"});
  EXPECT_EQ(heated.names, want);
  EXPECT_EQ(heated.note, "");

  MasterLog unpolled = test::record_log(test::plan_scenario(kPlanLoad_gcm2), default_model_card());
  for (MasterLogRow& row : unpolled.rows) row.temperature_C.reset();
  const DefaultFit none = default_fit(cases_for(unpolled, plan), default_model_card());
  EXPECT_EQ(none.names, default_fit_names());
  EXPECT_EQ(none.note, ""); // no temperatures: nothing to say
}

// Issue 26: with one more wire count of random noise on every logged
// position (seeded), the same; issue 36's tolerances (identified within
// 10 %, the held-out move within 5 % and max(5 %, 2 ms)). Skipped under the
// sanitizers like the fit above.
TEST(Calibration, WithOneCountOfNoise) {
  if (kSanitized) GTEST_SKIP() << "13 s of CPU in Release; checked in the Release stage";
  const Scenario plan = test::plan_scenario(kPlanLoad_gcm2);
  const ModelCard hidden = hidden_card();
  const auto cases = cases_for(test::record_log(plan, hidden, 26u), plan);
  const FitResult fit = fit_model(cases, default_model_card(), FitOptions{});
  std::printf("rms %.5f deg (start %.5f), %d iterations, %zu replays, %s\n", fit.rms_residual_deg,
              fit.start_rms_residual_deg, fit.iterations, fit.replays, fit.solver_message.c_str());
  EXPECT_TRUE(fit.converged);
  EXPECT_TRUE(fit.adequate) << fit.inadequacy;
  expect_recovered(fit, hidden, 0.10, 0);
  expect_predicts_held_out(fit.card, hidden, 0.05);
}

} // namespace
} // namespace sreh
