// Roses of contact normals and histograms of obliquity on contacts whose
// directions and forces are set by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dem/analysis/distributions.h"

namespace dem::analysis {
namespace {

constexpr double kPi = std::numbers::pi;

// Particles 0..n, contact c between 0 and c+1 along the angle given, with a
// normal force and a signed shear force along t (e turned clockwise).
AssemblySample star(const std::vector<double>& angles, const std::vector<double>& normal,
                    const std::vector<double>& shear, const std::vector<bool>& sliding) {
  AssemblySample s;
  s.position.push_back({0.0, 0.0});
  s.radius.push_back(1.0);
  for (std::size_t k = 0; k < angles.size(); ++k) {
    const Vec2 e(std::cos(angles[k]), std::sin(angles[k]));
    s.position.push_back(2.0 * e);
    s.radius.push_back(1.0);
    ContactRecord c;
    c.first = ParticleId{0};
    c.second_particle = ParticleId::from_index(k + 1);
    c.normal = e;
    c.point = e;
    c.normal_force = normal[k];
    c.shear_force = shear[k];
    c.force = -normal[k] * e - shear[k] * Vec2(e.y(), -e.x());
    c.sliding = sliding[k];
    s.contacts.push_back(c);
  }
  return s;
}

TEST(Distributions, RoseCountsEachNormalAtBothEnds) {
  // Normals at 10, 100 and 100 degrees; the second twice as loaded.
  const double d = kPi / 180.0;
  const AssemblySample s = star({10 * d, 100 * d, 100.5 * d}, {1.0, 2.0, 2.0}, {0.0, 0.0, 0.0}, {false, true, false});
  const auto rose = normal_rose(s, Region{"all"}, 36, RoseOf::kContacts);
  ASSERT_EQ(rose.size(), 36u);
  EXPECT_EQ(rose[1].contacts, 1);   // 10 deg
  EXPECT_EQ(rose[19].contacts, 1);  // 190 deg
  EXPECT_EQ(rose[10].contacts, 2);  // 100 and 100.5 deg
  EXPECT_EQ(rose[28].contacts, 2);
  EXPECT_NEAR(rose[10].share, 2.0 / 6.0, 1e-12);
  const auto weighted = normal_rose(s, Region{"all"}, 36, RoseOf::kNormalForce);
  EXPECT_NEAR(weighted[10].share, 4.0 / 10.0, 1e-12);
  EXPECT_NEAR(weighted[1].share, 1.0 / 10.0, 1e-12);
  const auto sliding = normal_rose(s, Region{"all"}, 36, RoseOf::kSlidingContacts);
  EXPECT_NEAR(sliding[10].share, 0.5, 1e-12);
  EXPECT_EQ(sliding[1].contacts, 0);
}

TEST(Distributions, ObliquitiesFromMinusOneToOne) {
  // mu = 0.5: F_s / (mu F_n) = -1 (sliding), 0.2, 0.99, 1.
  const AssemblySample s =
      star({0.0, 1.0, 2.0, 3.0}, {2.0, 2.0, 2.0, 2.0}, {-1.0, 0.2, 0.99, 1.0}, {true, false, false, true});
  const auto histogram = obliquity_histogram(s, Region{"all"}, 0.5, 20);
  ASSERT_EQ(histogram.size(), 20u);
  EXPECT_EQ(histogram[0].contacts, 1);   // [-1, -0.9)
  EXPECT_EQ(histogram[12].contacts, 1);  // 0.2 in [0.2, 0.3)
  EXPECT_EQ(histogram[19].contacts, 2);  // 0.99 and 1 in the last class
  EXPECT_NEAR(histogram[19].share, 0.5, 1e-12);
  EXPECT_NEAR(histogram[0].low, -1.0, 1e-12);
}

}  // namespace
}  // namespace dem::analysis
