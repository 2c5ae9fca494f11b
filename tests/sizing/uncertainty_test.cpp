// size --uncertainty (issue 26): bands over the model card's ranges bracket
// the nominal, repeat bit for bit with the seed, and narrow with a
// calibrated model's narrower ranges.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "sizing/uncertainty.hpp"
#include "sizing/uncertainty_parts.hpp"

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
}

// Issue 35: every constant the card gives a range wider than one value is
// sampled, the loop tuning included (no list of names in the code); those
// with a range of one value are held and listed as held.
TEST(Uncertainty, SamplesEveryConstantWithARangeAndListsTheRest) {
  const ModelCard& card = default_model_card();
  const auto cards = latin_hypercube_cards(card, 6, 3);
  SizingRequest rq = request();
  rq.cycles = 1;
  const SizingResult nominal = size(rq);
  const UncertaintyResult u = size_uncertainty(rq, card, nominal.evaluation, 2, 3, 2);
  EXPECT_EQ(u.sampled.size() + u.fixed.size(), card.constants.size());
  for (std::size_t c = 0; c < card.constants.size(); ++c) {
    const ModelConstant& k = card.constants[c];
    const bool ranged = k.range_hi > k.range_lo;
    const auto& list = ranged ? u.sampled : u.fixed;
    EXPECT_NE(std::find(list.begin(), list.end(), k.name), list.end()) << k.name;
    double lo = INFINITY, hi = -INFINITY;
    for (const ModelCard& s : cards) {
      lo = std::min(lo, s.constants[c].value);
      hi = std::max(hi, s.constants[c].value);
      EXPECT_GE(s.constants[c].value, k.range_lo) << k.name;
      EXPECT_LE(s.constants[c].value, k.range_hi) << k.name;
    }
    if (ranged && !model_constant_is_whole(k.name)) {
      EXPECT_LT(lo, hi) << k.name << " is not sampled";
    }
    if (!ranged) {
      EXPECT_EQ(lo, hi) << k.name << " has no range but varies";
    }
  }
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

// Issue 35: a sample that does not complete is infeasible, never left out;
// every sample is in the count or a failure group, named in words; the
// sentence says how many of how many.
TEST(Uncertainty, VerdictCountsEverySampleAndNamesTheLimitInWords) {
  using uncertainty_parts::Outcome;
  Outcome ok;
  ok.completed = ok.feasible = true;
  Outcome torque = ok;
  torque.feasible = false;
  torque.binding_limit = "torque_at_speed";
  torque.reason = "peak torque 0.560 N m is above 90 % of the motor's 0.600 N m";
  Outcome stuck;
  stuck.binding_limit = "settling";
  stuck.reason = "move 1 to 90 deg failed: error 0x01: settling timeout (114.8)";
  const std::vector<Outcome> samples = {ok, torque, ok, stuck, torque, ok};
  const SampleVerdict v = uncertainty_parts::verdict_of(ok, samples);
  EXPECT_EQ(v.samples, 6);
  EXPECT_EQ(v.feasible, 3);
  EXPECT_EQ(v.incomplete, 1);
  EXPECT_FALSE(v.all());
  ASSERT_EQ(v.failures.size(), 2u);
  EXPECT_EQ(v.failures[0].limit, "torque_at_speed"); // most samples first
  EXPECT_EQ(v.failures[0].samples, (std::vector<int>{2, 5}));
  EXPECT_EQ(v.failures[1].incomplete, 1);
  const std::string s = v.sentence();
  EXPECT_NE(s.find("feasible in 3 of 6 samples: at risk"), std::string::npos) << s;
  EXPECT_NE(s.find(limit_words("torque_at_speed") + " in 2"), std::string::npos) << s;
  EXPECT_EQ(s.find("torque_at_speed"), std::string::npos) << s;
  EXPECT_NE(s.find("1 of them not completed"), std::string::npos) << s;
  const UncertaintyResult u = uncertainty_parts::bands(default_model_card(), 6, 1, ok, samples);
  EXPECT_FALSE(u.feasible_worst_case);
  EXPECT_EQ(u.infeasible_samples, 3);
  EXPECT_EQ(u.banded, 6); // the nominal and the 5 completed samples
  EXPECT_TRUE(uncertainty_parts::verdict_of(ok, {ok, ok}).all());
  EXPECT_FALSE(uncertainty_parts::verdict_of(torque, {ok, ok}).all()); // the nominal counts too
}

TEST(Uncertainty, BandPercentilesLieBetweenTheExtremes) {
  const Band b = band_of({5, 1, 4, 2, 3});
  EXPECT_EQ(b.lo, 1);
  EXPECT_EQ(b.hi, 5);
  EXPECT_EQ(b.median, 3);
  EXPECT_GT(b.p95, b.median);
  EXPECT_LT(b.p95, b.hi);
  EXPECT_GT(b.p5, b.lo);
}

} // namespace
} // namespace sreh::sizing
