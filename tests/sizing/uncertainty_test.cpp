// size --uncertainty (issue 26): bands over the model card's ranges bracket
// the nominal, repeat bit for bit with the seed, and narrow with a
// calibrated model's narrower ranges.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "sizing/uncertainty.hpp"

namespace sreh::sizing {
namespace {

SizingRequest request() {
  SizingRequest rq;
  rq.angle_deg = 90;
  rq.world.load = InertiaLoad{5000};
  rq.setting = MotionSetting{2000, 100, 100};
  rq.settling.tolerance_deg = 0.0103; // tight, no waiting time: the settling shows the drive train
  rq.settling.wait_ms = 0;
  return rq;
}

UncertaintyResult bands(const ModelCard& card, uint64_t seed, int threads) {
  SizingRequest rq = request();
  rq.world.module = card.module_model();
  const SizingResult nominal = size(rq);
  return size_uncertainty(rq, card, nominal.evaluation, 8, seed, threads);
}

TEST(Uncertainty, BandsBracketTheNominalAndRepeatWithTheSeed) {
  SizingRequest rq = request();
  const SizingResult nominal = size(rq);
  const UncertaintyResult a = bands(default_model_card(), 7, 2);
  EXPECT_LE(a.positioning_s.lo, nominal.evaluation.positioning_s);
  EXPECT_GE(a.positioning_s.hi, nominal.evaluation.positioning_s);
  EXPECT_LT(a.positioning_s.lo, a.positioning_s.hi);
  EXPECT_LT(a.peak_torque_Nm.lo, a.peak_torque_Nm.hi);
  EXPECT_LT(a.max_temperature_C.lo, a.max_temperature_C.hi);
  const UncertaintyResult b = bands(default_model_card(), 7, 1); // other thread count, same answer
  EXPECT_EQ(a.positioning_s.lo, b.positioning_s.lo);
  EXPECT_EQ(a.positioning_s.hi, b.positioning_s.hi);
  EXPECT_EQ(a.peak_torque_Nm.hi, b.peak_torque_Nm.hi);
  EXPECT_EQ(a.max_temperature_C.hi, b.max_temperature_C.hi);
}

// size --cycle --uncertainty: the cycle with the nominal answer's sets on
// every sampled model; the bands bracket the nominal cycle and repeat.
TEST(Uncertainty, CycleBandsBracketTheNominalCycle) {
  // Given sets: no search, so the test stays cheap under the sanitizers.
  const CycleRequest rq = parse_cycle_file(std::string(SREH_SOURCE_DIR) + "/examples/cycles/indexing_table.yaml");
  const CycleResult nominal = size_cycle(rq);
  ASSERT_TRUE(nominal.evaluation.completed);
  const CyclePlan plan = plan_sets(rq);
  const auto run = [&](int threads) {
    return cycle_uncertainty(rq, plan, nominal.settings, default_model_card(), nominal.evaluation, 4, 11, threads);
  };
  const UncertaintyResult a = run(2);
  ASSERT_TRUE(a.cycle_s.has_value());
  EXPECT_LE(a.cycle_s->lo, nominal.evaluation.cycle_s);
  EXPECT_GE(a.cycle_s->hi, nominal.evaluation.cycle_s);
  EXPECT_LE(a.peak_torque_Nm.lo, nominal.evaluation.peak_torque_Nm);
  EXPECT_GE(a.peak_torque_Nm.hi, nominal.evaluation.peak_torque_Nm);
  EXPECT_LT(a.peak_torque_Nm.lo, a.peak_torque_Nm.hi);
  EXPECT_LT(a.max_temperature_C.lo, a.max_temperature_C.hi);
  const UncertaintyResult b = run(1);
  EXPECT_EQ(a.cycle_s->hi, b.cycle_s->hi);
  EXPECT_EQ(a.max_temperature_C.hi, b.max_temperature_C.hi);
  EXPECT_EQ(a.feasible_worst_case, b.feasible_worst_case);
}

TEST(Uncertainty, LatinHypercubeHasOneSampleInEveryStratum) {
  const ModelCard& card = default_model_card();
  const auto cards = latin_hypercube_cards(card, 8, 3);
  const ModelConstant* k = card.find("torsional_stiffness");
  const std::size_t c = static_cast<std::size_t>(k - card.constants.data());
  std::vector<int> hits(8, 0);
  for (const ModelCard& s : cards) {
    const double u = (s.constants[c].value - k->range_lo) / (k->range_hi - k->range_lo);
    ++hits[static_cast<std::size_t>(std::min(7.0, u * 8))];
  }
  for (int h : hits) EXPECT_EQ(h, 1);
  for (const ModelCard& s : cards) EXPECT_EQ(s.find("velocity_bandwidth")->value, card.find("velocity_bandwidth")->value); // firmware: kept
}

TEST(Uncertainty, NarrowerRangesGiveANarrowerBand) {
  ModelCard calibrated = default_model_card();
  for (ModelConstant& c : calibrated.constants) { // +-2 % around the value: what a fit leaves open
    if (c.range_hi > c.range_lo && !model_constant_is_whole(c.name)) {
      c.range_lo = std::max(c.range_lo, 0.98 * c.value);
      c.range_hi = std::min(c.range_hi, 1.02 * c.value);
    }
  }
  const UncertaintyResult wide = bands(default_model_card(), 7, 2);
  const UncertaintyResult narrow = bands(calibrated, 7, 2);
  EXPECT_LT(narrow.peak_torque_Nm.hi - narrow.peak_torque_Nm.lo, wide.peak_torque_Nm.hi - wide.peak_torque_Nm.lo);
  EXPECT_LT(narrow.max_temperature_C.hi - narrow.max_temperature_C.lo, wide.max_temperature_C.hi - wide.max_temperature_C.lo);
}

} // namespace
} // namespace sreh::sizing
