// The force distribution's numbers (Miyata et al. 2002, 3.3(2), eqs. 61-62,
// Figs. 35 and 37) against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "dem/analysis/force_distribution.h"

namespace dem::analysis {
namespace {

// Midpoint rule over [0, 60]: the densities have decayed by then.
double integral(const std::function<double(double)>& g) {
  constexpr int kSteps = 60000;
  double sum = 0.0;
  for (int k = 0; k < kSteps; ++k) sum += g((k + 0.5) * 1e-3);
  return sum * 1e-3;
}

TEST(ForceDistribution, TheQModelIsAUnitMeanDensity) {
  // Miyata eq. 62 with N = 3: 27/2 f^2 e^(-3f), a gamma density of mean 1.
  EXPECT_NEAR(q_model_density(1.0, 3), 13.5 * std::exp(-3.0), 1e-15);
  EXPECT_NEAR(integral([](double f) { return q_model_density(f, 3); }), 1.0, 1e-9);
  EXPECT_NEAR(integral([](double f) { return f * q_model_density(f, 3); }), 1.0, 1e-9);
  EXPECT_EQ(q_model_density(-0.5, 3), 0.0);
}

TEST(ForceDistribution, MuethsFitAsPublished) {
  // Miyata eq. 61 with a = 3, b = 0.75, beta = 1.5; it carries 0.989 of a unit mass.
  EXPECT_DOUBLE_EQ(mueth_density(0.0), 0.75);
  EXPECT_NEAR(mueth_density(1.0), 3.0 * (1.0 - 0.75 * std::exp(-1.0)) * std::exp(-1.5), 1e-15);
  EXPECT_NEAR(integral([](double f) { return mueth_density(f); }), 0.989, 1e-3);
}

TEST(ForceDistribution, ForcesAreNormalisedByTheirMean) {
  const std::vector<double> forces = {1.0, 2.0, 3.0, 6.0};
  const std::vector<double> f = normalised_forces(forces);
  ASSERT_EQ(f.size(), 4u);
  EXPECT_DOUBLE_EQ(f[0], 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(f[3], 2.0);
  EXPECT_DOUBLE_EQ(std::accumulate(f.begin(), f.end(), 0.0), 4.0);
  EXPECT_TRUE(normalised_forces(std::vector<double>{0.0, 0.0}).empty());
  EXPECT_TRUE(normalised_forces({}).empty());
}

TEST(ForceDistribution, ClassesHoldADensityAndTheLoadShares) {
  const std::vector<double> f = {0.1, 0.2, 0.5, 0.9, 1.0, 1.3, 2.0};
  const std::vector<ForceClass> classes = force_classes(f, 0.5);
  ASSERT_EQ(classes.size(), 5u);  // up to and including the class of 2.0
  EXPECT_EQ(classes[0].contacts, 2);
  EXPECT_EQ(classes[1].contacts, 2);  // 0.5 opens the second class
  EXPECT_EQ(classes[2].contacts, 2);
  EXPECT_EQ(classes[4].contacts, 1);
  EXPECT_DOUBLE_EQ(classes[4].f_low, 2.0);
  double density = 0.0, share = 0.0;
  for (const ForceClass& c : classes) {
    density += c.probability_density * (c.f_high - c.f_low);
    share += c.load_share;
  }
  EXPECT_DOUBLE_EQ(density, 1.0);
  EXPECT_DOUBLE_EQ(share, 1.0);
  EXPECT_DOUBLE_EQ(classes[0].load_share, 0.3 / 6.0);
  EXPECT_TRUE(force_classes(f, 0.0).empty());
}

TEST(ForceDistribution, TheTailRateOfExponentialForces) {
  // Quantiles of f = 1 + Exp(rate 2), and some forces below the tail.
  std::vector<double> f = {0.2, 0.5, 0.8};
  const int n = 2000;
  for (int k = 1; k <= n; ++k) f.push_back(1.0 - std::log(1.0 - (k - 0.5) / n) / 2.0);
  const TailFit fit = fit_exponential_tail(f, 1.0);
  EXPECT_EQ(fit.contacts, n);
  EXPECT_NEAR(fit.decay_rate, 2.0, 0.02);
  EXPECT_NEAR(fit.decay_rate_error, fit.decay_rate / std::sqrt(n), 1e-12);
  EXPECT_NEAR(fit.excess_cv, 1.0, 0.02);
  EXPECT_EQ(fit_exponential_tail(std::vector<double>{0.5}, 1.0).decay_rate, 0.0);
}

TEST(ForceDistribution, ATailCutOffIsNotExponential) {
  // f spread evenly over (1, 2]: a rate is still estimated, but the
  // excesses vary like a uniform's, 1/sqrt(3) of their mean.
  std::vector<double> f;
  const int n = 1000;
  for (int k = 1; k <= n; ++k) f.push_back(1.0 + (k - 0.5) / n);
  const TailFit fit = fit_exponential_tail(f, 1.0);
  EXPECT_NEAR(fit.decay_rate, 2.0, 1e-9);
  EXPECT_NEAR(fit.excess_cv, 1.0 / std::sqrt(3.0), 0.01);
}

TEST(ForceDistribution, TheSameEstimatorOnTheSeedsDensities) {
  // An exponential has no memory: its rate from anywhere.
  EXPECT_NEAR(tail_decay_rate([](double f) { return 1.5 * std::exp(-1.5 * f); }, 1.0), 1.5, 1e-9);
  // Eq. 62, N = 3: E[f - 1 | f > 1] = 4.5 / 8.5, integrating the gamma tail by parts.
  EXPECT_NEAR(tail_decay_rate([](double f) { return q_model_density(f, 3); }, 1.0), 8.5 / 4.5, 1e-9);
  // Eq. 61: exp(-f^2) has died out beyond f = 1, so nearly Mueth's beta.
  const double mueth = tail_decay_rate([](double f) { return mueth_density(f); }, 1.0);
  EXPECT_GT(mueth, 1.3);
  EXPECT_LT(mueth, 1.5);
}

}  // namespace
}  // namespace dem::analysis
