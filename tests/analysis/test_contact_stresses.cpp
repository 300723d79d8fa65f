// Contact stresses of Hertzian contacts (Randall 1989, 4.6) on contacts
// whose overlaps and forces are set by hand, and the moments that judge
// how near a normal distribution Figs. 6.42-6.43's histograms lie.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "dem/analysis/contact_stresses.h"

namespace dem::analysis {
namespace {

constexpr double kPi = std::numbers::pi;

ContactRecord touching(int first, int second, const AssemblySample& s, double overlap, double normal_force,
                       double shear_force) {
  ContactRecord c;
  c.first = ParticleId{first};
  c.second_particle = ParticleId{second};
  const Vec2 d = s.position[static_cast<std::size_t>(second)] - s.position[static_cast<std::size_t>(first)];
  c.normal = d.normalized();
  c.point = s.position[static_cast<std::size_t>(first)] + 0.5 * d;
  c.overlap = overlap;
  c.normal_force = normal_force;
  c.shear_force = shear_force;
  return c;
}

// Two spheres of radius 1 and one of 0.5 in a row along x, and a fourth
// of radius 1 far away, touching nothing.
AssemblySample row() {
  AssemblySample s;
  s.position = {{0.0, 0.0}, {1.99, 0.0}, {3.34, 0.0}, {20.0, 0.0}};
  s.radius = {1.0, 1.0, 0.5, 1.0};
  s.contacts.push_back(touching(0, 1, s, 0.02, 1.0, -0.5));
  s.contacts.push_back(touching(1, 2, s, 0.15, 3.0, 0.0));
  return s;
}

TEST(ContactStresses, HertzContactRadiusAndMeanStresses) {
  const ContactStressStatistics st = contact_stresses(row(), Region{"all"});
  ASSERT_EQ(st.contacts.size(), 2u);
  // R* = 0.5, a = (0.5 * 0.02)^(1/2) = 0.1 (Randall 3.12).
  const ContactStress& a = st.contacts[0];
  EXPECT_NEAR(a.contact_radius, 0.1, 1e-12);
  EXPECT_NEAR(a.normal_stress, 1.0 / (kPi * 0.01), 1e-9);
  EXPECT_NEAR(a.shear_stress, 0.5 / (kPi * 0.01), 1e-9);
  EXPECT_NEAR(a.radius_ratio, 0.1, 1e-12);
  EXPECT_NEAR(a.overlap_ratio, 0.01, 1e-12);
  // R* = 1/3, a = (0.15 / 3)^(1/2); the smaller sphere's diameter is 1.
  const ContactStress& b = st.contacts[1];
  EXPECT_NEAR(b.contact_radius, std::sqrt(0.05), 1e-12);
  EXPECT_NEAR(b.radius_ratio, std::sqrt(0.05) / 0.5, 1e-12);
  EXPECT_NEAR(b.overlap_ratio, 0.15, 1e-12);
  // Only the second is past 7 % of the smaller diameter (Randall 6.4.3).
  EXPECT_EQ(st.over_overlap_limit, 1);
  EXPECT_NEAR(st.largest_overlap_ratio, 0.15, 1e-12);
  EXPECT_EQ(st.normal_stress.count, 2);
  EXPECT_NEAR(st.normal_stress.mean, 0.5 * (a.normal_stress + b.normal_stress), 1e-9);
}

TEST(ContactStresses, ARegionTakesTheContactsWhosePointLiesInside) {
  Region left{"left"};
  left.shape = RegionShape::kBall;
  left.centre = {1.0, 0.0};
  left.radius = 0.5;
  const ContactStressStatistics st = contact_stresses(row(), left);
  ASSERT_EQ(st.contacts.size(), 1u);
  EXPECT_NEAR(st.contacts[0].contact_radius, 0.1, 1e-12);
  EXPECT_EQ(st.over_overlap_limit, 0);
}

TEST(ContactStresses, EachSizeContributesItsContactEnds) {
  const ContactStressStatistics st = contact_stresses(row(), Region{"all"});
  ASSERT_EQ(st.sizes.size(), 2u);
  EXPECT_DOUBLE_EQ(st.sizes[0].radius, 0.5);
  EXPECT_EQ(st.sizes[0].particles, 1);
  EXPECT_EQ(st.sizes[0].contacts, 1);
  EXPECT_NEAR(st.sizes[0].share, 0.25, 1e-12);
  EXPECT_EQ(st.sizes[1].particles, 3);
  EXPECT_EQ(st.sizes[1].contacts, 3);
  EXPECT_EQ(st.sizes[1].without_contacts, 1);  // the sphere far away
  EXPECT_NEAR(st.sizes[1].coordination, 1.0, 1e-12);
}

TEST(ContactStresses, SmallForcesAreLeftOutOfTheSecondMoments) {
  AssemblySample s = row();
  s.contacts[0].normal_force = 0.05;  // below a tenth of the mean, (0.05 + 3) / 2
  const ContactStressStatistics st = contact_stresses(s, Region{"all"});
  EXPECT_EQ(st.normal_stress.count, 2);
  EXPECT_EQ(st.normal_stress_without_small.count, 1);
  EXPECT_NEAR(st.normal_stress_without_small.mean, st.contacts[1].normal_stress, 1e-9);
}

TEST(Moments, OfAKnownSample) {
  const std::vector<double> v = {1, 2, 3, 4, 5};
  const Moments m = moments_of(v);
  EXPECT_EQ(m.count, 5);
  EXPECT_DOUBLE_EQ(m.min, 1.0);
  EXPECT_DOUBLE_EQ(m.max, 5.0);
  EXPECT_NEAR(m.mean, 3.0, 1e-12);
  EXPECT_NEAR(m.standard_deviation, std::sqrt(2.5), 1e-12);
  EXPECT_NEAR(m.skewness, 0.0, 1e-12);
  EXPECT_NEAR(m.excess_kurtosis, 6.8 / 4.0 - 3.0, 1e-12);  // m4 = 6.8, m2 = 2
  EXPECT_NEAR(m.within_one_deviation, 0.6, 1e-12);
  EXPECT_NEAR(m.within_two_deviations, 1.0, 1e-12);
  // Three zeros and a one: skewness 2 / sqrt(3).
  EXPECT_NEAR(moments_of(std::vector<double>{0, 0, 0, 1}).skewness, 2.0 / std::sqrt(3.0), 1e-12);
  EXPECT_EQ(moments_of(std::vector<double>{}).count, 0);
  EXPECT_EQ(moments_of(std::vector<double>{2, 2}).skewness, 0.0);
}

TEST(Moments, ANormalSampleReadsNormal) {
  std::mt19937_64 random(1989);
  std::normal_distribution<double> normal(10.0, 2.0);
  std::vector<double> v(200000);
  for (double& x : v) x = normal(random);
  const Moments m = moments_of(v);
  EXPECT_NEAR(m.mean, 10.0, 0.02);
  EXPECT_NEAR(m.standard_deviation, 2.0, 0.02);
  EXPECT_NEAR(m.skewness, 0.0, 0.03);
  EXPECT_NEAR(m.excess_kurtosis, 0.0, 0.05);
  EXPECT_NEAR(m.within_one_deviation, 0.683, 0.005);
  EXPECT_NEAR(m.within_two_deviations, 0.954, 0.003);
}

}  // namespace
}  // namespace dem::analysis
