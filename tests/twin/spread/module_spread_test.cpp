// Issue 35: the card's ranges are a production spread of working modules.
// Every Latin-hypercube sample of every constant's range (64, fixed seed),
// in each mounting, holds still after Motor On and after its moves (no
// limit cycle: the commanded torque stays within kHoldRipple_Nm peak to
// peak) and completes rated moves to 90, -90 and 0 deg without an error
// (114.x). SREH_SPREAD_VERBOSE=1 prints every run's figures.
// docs/model-card.md "Ranges" says what was narrowed and why.
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <sstream>

#include "tests/twin/spread/module_spread.hpp"

namespace sreh::test {
namespace {

// Holding ripple allowed (docs/model-card.md "Ranges", A-TWIN-47):
// friction-bounded hunting, the spread's largest breakaway (0.01 + 0.006)
// and cogging (0.01 N m) both ways; a limit cycle is 0.3..1.2 N m (the
// issue's was +-0.59 N m).
constexpr double kHoldRipple_Nm = 0.1;

std::string describe(const std::vector<std::pair<std::string, double>>& values) {
  std::ostringstream s;
  for (const auto& [name, value] : values) s << name << '=' << value << ' ';
  return s.str();
}

void expect_works(const SpreadRun& r, const std::string& what) {
  EXPECT_TRUE(r.ready) << what;
  EXPECT_EQ(r.moves_completed, 3) << what << "error code " << int{r.error_code};
  EXPECT_EQ(r.error_code, 0) << what;
  EXPECT_LE(r.after_motor_on.torque_peak_to_peak_Nm, kHoldRipple_Nm) << what << "after Motor On";
  EXPECT_LE(r.after_moves.torque_peak_to_peak_Nm, kHoldRipple_Nm) << what << "after the moves";
}

void report(const SpreadRun& r, Mounting m, const std::string& values) {
  if (std::getenv("SREH_SPREAD_VERBOSE") == nullptr) return;
  std::cout << mounting_name(m) << ": ready " << r.ready << " moves " << r.moves_completed << " error "
            << int{r.error_code} << " hold ripple " << r.after_motor_on.torque_peak_to_peak_Nm << " / "
            << r.after_moves.torque_peak_to_peak_Nm << " N m, band " << r.after_motor_on.position_band_deg << " / "
            << r.after_moves.position_band_deg << " deg, settling " << r.max_settling_s * 1e3 << " ms  " << values << "\n";
}

constexpr Mounting kMountings[] = {Mounting::VerticalEmpty, Mounting::VerticalRatedDisk, Mounting::HorizontalRatedArm};

TEST(ModuleSpread, TheCardsModuleHoldsAndMovesInEveryMounting) {
  for (Mounting m : kMountings) {
    const SpreadRun r = run_module(module_with({}), m);
    report(r, m, "card");
    expect_works(r, std::string(mounting_name(m)) + ": ");
  }
}

TEST(ModuleSpread, EveryLatinHypercubeSampleOfTheRangesHoldsAndMoves) {
  const auto samples = latin_hypercube(64, 35);
  ASSERT_EQ(samples.size(), 64u);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const ModuleModel module = module_with(samples[i]);
    for (Mounting m : kMountings) {
      const SpreadRun r = run_module(module, m);
      const std::string values = describe(samples[i]);
      report(r, m, values);
      expect_works(r, "sample " + std::to_string(i) + ", " + mounting_name(m) + ": " + values + "\n");
    }
  }
}

} // namespace
} // namespace sreh::test
