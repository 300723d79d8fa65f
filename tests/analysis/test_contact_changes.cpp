// The contacts broken and formed between two states (Randall 1989, Fig.
// 6.35) on samples set by hand, matched by the world's ids.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/analysis/contact_changes.h"

namespace dem::analysis {
namespace {

ContactRecord bond(int first, int second, const Vec2& normal) {
  ContactRecord c;
  c.first = ParticleId{first};
  c.second_particle = ParticleId{second};
  c.normal = normal.normalized();
  c.overlap = 1e-6;
  return c;
}

// Four particles with world ids 10, 11, 12, 13 at the corners of a square.
AssemblySample square() {
  AssemblySample s;
  s.position = {{0, 0}, {2, 0}, {0, 2}, {2, 2}};
  s.radius = {1, 1, 1, 1};
  s.ids = {ParticleId{10}, ParticleId{11}, ParticleId{12}, ParticleId{13}};
  return s;
}

TEST(ContactChanges, BrokenFormedAndKeptByTheWorldsIds) {
  AssemblySample before = square();
  before.contacts = {bond(0, 1, {1, 0}), bond(0, 2, {0, 1}), bond(3, 1, {0, -1})};
  before.contacts[0].point = {1, 0};
  before.contacts[1].point = {0, 1};
  before.contacts[2].point = {2, 1};
  // Later the same particles sit in another order in the sample; the
  // horizontal contact 10-11 broke, 12-13 formed, 10-12 and 11-13 stayed.
  AssemblySample after = square();
  std::swap(after.position[0], after.position[3]);
  std::swap(after.ids[0], after.ids[3]);
  after.contacts = {bond(3, 2, {0, 1}), bond(2, 0, {1, 0}), bond(1, 0, {0, 1})};
  after.contacts[0].point = {0, 1};
  after.contacts[1].point = {1, 2};
  after.contacts[2].point = {2, 1};
  const ContactChanges changes = contact_changes(before, after, Region{"all"});
  ASSERT_EQ(changes.broken.size(), 1u);
  EXPECT_EQ(changes.broken[0].first, ParticleId{10});
  EXPECT_EQ(changes.broken[0].second, ParticleId{11});
  ASSERT_EQ(changes.formed.size(), 1u);
  EXPECT_EQ(changes.formed[0].first, ParticleId{12});
  EXPECT_EQ(changes.formed[0].second, ParticleId{13});
  EXPECT_EQ(changes.kept.size(), 2u);
}

TEST(ContactChanges, ARegionTakesTheContactsWhosePointLiesInside) {
  AssemblySample before = square();
  before.contacts = {bond(0, 1, {1, 0}), bond(2, 3, {1, 0})};
  before.contacts[0].point = {1, 0};
  before.contacts[1].point = {1, 2};
  Region lower{"lower"};
  lower.shape = RegionShape::kBox;
  lower.min = {-1, -1};
  lower.max = {3, 1};
  const ContactChanges changes = contact_changes(before, square(), lower);
  ASSERT_EQ(changes.broken.size(), 1u);
  EXPECT_EQ(changes.broken[0].second, ParticleId{11});
}

TEST(ContactChanges, ShareWithin45DegreesOfAnAxis) {
  const double d = std::acos(-1.0) / 180.0;
  std::vector<Bond> bonds;
  for (const double angle : {0.0, 30.0, 150.0, 200.0, 60.0, 90.0, 100.0, 270.0})
    bonds.push_back({ParticleId{0}, ParticleId{1}, Vec2(std::cos(angle * d), std::sin(angle * d))});
  EXPECT_NEAR(share_along(bonds, {1, 0}), 0.5, 1e-12);  // 0, 30, 150, 200
  EXPECT_NEAR(share_along(bonds, {0, 2}), 0.5, 1e-12);  // 60, 90, 100, 270
  EXPECT_EQ(share_along({}, {1, 0}), 0.0);
}

}  // namespace
}  // namespace dem::analysis
