// The three states of a plate loading test and its stress drops (Miyata et
// al. 2002, 3.2(3), Fig. 26) on curves whose answers are known.
#include <gtest/gtest.h>

#include <vector>

#include "dem/analysis/loading_states.h"
#include "dem/analysis/stress_drops.h"

namespace dem::analysis {
namespace {

CompressionSample sample(std::uint64_t cycle, double settlement, double stress, int contacts) {
  CompressionSample s;
  s.cycle = cycle;
  s.settlement = settlement;
  s.stress = stress;
  s.loading_contacts = contacts;
  return s;
}

// A plate that approaches for 10 samples, then meets a sample that
// stiffens: 1e5 Pa/m to 50 kPa, 1e6 Pa/m to 250 kPa, then 4e6 Pa/m, a
// millimetre a sample (stresses in whole pascals, so the bounds are met
// exactly).
std::vector<CompressionSample> three_states() {
  std::vector<CompressionSample> samples;
  std::uint64_t cycle = 0;
  int step = 0;
  const auto add = [&](double stress, int contacts) {
    samples.push_back(sample(cycle += 100, 0.001 * step++, stress, contacts));
  };
  for (int k = 0; k < 10; ++k) add(0.0, 0);
  for (int k = 1; k <= 500; ++k) add(100.0 * k, 2);
  for (int k = 1; k <= 200; ++k) add(50e3 + 1000.0 * k, 6);
  for (int k = 1; k <= 163; ++k) add(250e3 + 4000.0 * k, 8);
  return samples;
}

TEST(LoadingStates, StressBoundsGiveTheFirstCyclesOfEachState) {
  const std::vector<CompressionSample> samples = three_states();
  const StateCycles cycles = state_cycles(samples, 50e3, 250e3);
  ASSERT_TRUE(cycles.transition);
  ASSERT_TRUE(cycles.final);
  EXPECT_LT(*cycles.transition, *cycles.final);
  EXPECT_EQ(state_at(*cycles.transition - 1, cycles), LoadingState::kInitial);
  EXPECT_EQ(state_at(*cycles.transition, cycles), LoadingState::kTransition);
  EXPECT_EQ(state_at(*cycles.final, cycles), LoadingState::kFinal);
  EXPECT_EQ(state_at(0, state_cycles(samples, 1e7, 2e7)), LoadingState::kInitial);
  EXPECT_EQ(state_name(LoadingState::kTransition), "transition");
}

TEST(LoadingStates, EachStateIsFittedFromThePlatesFirstContact) {
  const std::vector<CompressionSample> samples = three_states();
  const std::array<StateFit, 3> fits = fit_states(samples, state_cycles(samples, 50e3, 250e3));
  EXPECT_EQ(fits[0].state, LoadingState::kInitial);
  // The approach is left out; 50 kPa opens the transition.
  EXPECT_EQ(fits[0].samples, 499);
  EXPECT_EQ(fits[1].samples, 200);
  EXPECT_EQ(fits[2].samples, 164);
  EXPECT_NEAR(fits[0].settlement_from, 0.010, 1e-12);
  EXPECT_NEAR(fits[0].tangent_stiffness, 1e5, 1e-3);
  EXPECT_NEAR(fits[0].secant_stiffness, 1e5, 1e-3);
  EXPECT_NEAR(fits[1].tangent_stiffness, 1e6, 1e-2);
  EXPECT_NEAR(fits[2].tangent_stiffness, 4e6, 1e-1);
  for (const StateFit& fit : fits) EXPECT_NEAR(fit.r_squared, 1.0, 1e-12);
  EXPECT_EQ(fits[0].loading_contacts_from, 2);
  EXPECT_EQ(fits[1].loading_contacts_from, 2);  // the 50 kPa sample
  EXPECT_EQ(fits[2].loading_contacts_to, 8);
}

TEST(LoadingStates, ContactsRisingFastThenSlowlyShowInTheRates) {
  std::vector<CompressionSample> samples;
  for (int k = 1; k <= 90; ++k) {
    const double stress = 10e3 * k;
    // One contact per 10 kPa up to 50 kPa, one per 100 kPa after.
    const int contacts = stress <= 50e3 ? k : 5 + static_cast<int>((stress - 50e3) / 100e3);
    samples.push_back(sample(100 * k, 0.01 * k, stress, contacts));
  }
  const std::array<StateFit, 3> fits = fit_states(samples, state_cycles(samples, 60e3, 250e3));
  EXPECT_NEAR(fits[0].contact_rate, 1e-4, 1e-6);
  EXPECT_LT(fits[1].contact_rate, fits[0].contact_rate / 5);
  EXPECT_LT(fits[2].contact_rate, fits[0].contact_rate / 5);
}

TEST(LoadingStates, AFallBelowABoundDoesNotReturnToAnEarlierState) {
  std::vector<CompressionSample> samples = three_states();
  samples.push_back(sample(samples.back().cycle + 100, samples.back().settlement, 200e3, 8));
  const StateCycles cycles = state_cycles(samples, 50e3, 250e3);
  EXPECT_EQ(state_at(samples.back().cycle, cycles), LoadingState::kFinal);
}

std::vector<CompressionSample> series(const std::vector<double>& stresses) {
  std::vector<CompressionSample> samples;
  for (std::size_t k = 0; k < stresses.size(); ++k)
    samples.push_back(sample(k, 0.001 * static_cast<double>(k), stresses[k], 3));
  return samples;
}

TEST(StressDrops, AReleaseInterruptedByASmallRecoveryCountsOnce) {
  // Up to 500 kPa, down to 440 with a 5 kPa recovery on the way, up again.
  const auto samples = series({300e3, 400e3, 500e3, 480e3, 470e3, 475e3, 450e3, 440e3, 460e3, 520e3});
  const std::vector<StressDrop> drops = find_stress_drops(samples, 0.02, {});
  ASSERT_EQ(drops.size(), 1u);
  EXPECT_EQ(drops[0].peak_cycle, 2u);
  EXPECT_EQ(drops[0].trough_cycle, 7u);
  EXPECT_DOUBLE_EQ(drops[0].peak_stress, 500e3);
  EXPECT_DOUBLE_EQ(drops[0].trough_stress, 440e3);
  EXPECT_DOUBLE_EQ(drops[0].relative(), 0.12);
  EXPECT_DOUBLE_EQ(drops[0].peak_settlement, 0.002);
}

TEST(StressDrops, WigglesBelowTheFractionAreNotDrops) {
  const auto samples = series({300e3, 400e3, 396e3, 410e3, 405e3, 420e3});
  EXPECT_TRUE(find_stress_drops(samples, 0.02, {}).empty());
  EXPECT_EQ(find_stress_drops(samples, 0.005, {}).size(), 2u);
}

TEST(StressDrops, AFallAtTheEndCountsAndDropsCarryTheirState) {
  const auto samples = series({40e3, 60e3, 30e3, 70e3, 300e3, 200e3});
  StateCycles cycles;
  cycles.transition = 1;
  cycles.final = 4;
  const std::vector<StressDrop> drops = find_stress_drops(samples, 0.02, cycles);
  ASSERT_EQ(drops.size(), 2u);
  EXPECT_EQ(drops[0].state, LoadingState::kTransition);
  EXPECT_EQ(drops[1].state, LoadingState::kFinal);
  EXPECT_EQ(drops[1].trough_cycle, 5u);
}

}  // namespace
}  // namespace dem::analysis
