// Cundall & Strack (1979) nine-disc test: Figs. 6 and 7 (damping, speed of
// loading) and Figs. 8-9 (distortion, k_s/k_n and friction angle), run from
// the cases in cases/ball/.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "nine_disc.h"

namespace dem::validation {
namespace {

const std::filesystem::path kCases = DEM_CASES_DIR "/ball";

TEST(NineDisc, Fig6DampingSettlesToTheSameEquilibrium) {
  const CompressionReport r = run_compression(kCases);
  const double feq = r.equilibrium_force;
  std::printf("F_eq %.6e; damped runs within %.4f%% of it; undamped mean %+.3f%% of F_eq, amplitude %.4f F_eq "
              "(seed: about 0.15)\n",
              feq, 100.0 * r.damped_spread, 100.0 * (r.undamped_mean / feq - 1.0), r.undamped_amplitude / feq);
  // Contact, global and both dampings reach the same F_eq within 1%.
  EXPECT_LT(r.damped_spread, 0.01);
  // Without damping the force oscillates about F_eq and does not settle.
  EXPECT_NEAR(r.undamped_mean / feq, 1.0, 0.01);
  EXPECT_GT(r.undamped_amplitude / feq, 0.05);
  EXPECT_LT(r.undamped_amplitude / feq, 0.5);
  // Damped: settled at the end (the last 500 cycles vary by under 1e-4 F_eq).
  const auto& f = r.damped.normal_force;
  const auto [lo, hi] = std::minmax_element(f.end() - 500, f.end());
  EXPECT_LT((*hi - *lo) / feq, 1e-4);
}

TEST(NineDisc, Fig7FasterLoadingGivesLargerOscillation) {
  const CompressionReport r = run_compression(kCases);
  std::printf("amplitude after loading: 0.12 per cycle %.4f F_eq, 0.04 per cycle %.4f F_eq\n",
              r.undamped_amplitude / r.equilibrium_force, r.slow_amplitude / r.equilibrium_force);
  EXPECT_GT(r.undamped_amplitude, 3.0 * r.slow_amplitude);
}

double largest_relative_difference(const ContactHistory& a, const ContactHistory& b, std::size_t from) {
  double worst = 0.0;
  for (std::size_t k = from; k < a.normal_force.size(); ++k) {
    worst = std::max(worst, std::abs(a.normal_force[k] - b.normal_force[k]) / a.normal_force[k]);
  }
  return worst;
}

TEST(NineDisc, Fig9StiffnessRatioMattersMoreAtHigherFriction) {
  const DistortionReport r = run_distortion(kCases);
  const std::size_t s = r.distortion_start;
  const double d15 = largest_relative_difference(r.phi15_ks2_3, r.phi15_ks1, s);
  const double d30 = largest_relative_difference(r.phi30_ks2_3, r.phi30_ks1, s);
  std::printf("largest difference of F_n at C between ks/kn = 2/3 and 1: phi 15 deg %.2f%%, phi 30 deg %.2f%%\n",
              100.0 * d15, 100.0 * d30);
  // Fig. 9(a): at 15 deg the two curves nearly coincide; Fig. 9(b): at 30 deg they deviate significantly.
  EXPECT_LT(d15, 0.03);
  EXPECT_GT(d30, 2.0 * d15);
}

TEST(NineDisc, Fig9bHighShearStiffnessStartsLowerPeaksThenSlips) {
  const DistortionReport r = run_distortion(kCases);
  const std::size_t s = r.distortion_start;
  const auto& low = r.phi30_ks2_3.normal_force;   // ks/kn = 2/3
  const auto& high = r.phi30_ks1.normal_force;    // ks/kn = 1
  // After undistorted compression F_n is less for ks/kn = 1 (the walls' shear carries more load).
  std::printf("phi 30: F_n at the start of distortion %.4e (ks/kn 2/3) vs %.4e (ks/kn 1)\n", low[s], high[s]);
  EXPECT_LT(high[s], low[s]);
  // As shearing proceeds the ks/kn = 1 force increases beyond the 2/3 one ...
  bool overtakes = false;
  for (std::size_t k = s; k < high.size(); ++k) overtakes = overtakes || high[k] > low[k];
  EXPECT_TRUE(overtakes);
  // ... reaches a maximum, after which slip sets in and the force falls back.
  const auto peak = std::max_element(high.begin() + static_cast<std::ptrdiff_t>(s), high.end());
  std::printf("phi 30, ks/kn 1: peak %.4e at distortion cycle %td, end %.4e\n", *peak,
              peak - high.begin() - static_cast<std::ptrdiff_t>(s), high.back());
  EXPECT_GT(*peak, 1.05 * high.back());
  EXPECT_LT(peak, high.end() - 100);
}

}  // namespace
}  // namespace dem::validation
