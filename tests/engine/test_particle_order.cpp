// The particles' order in memory (particle_order.h): a permutation that
// depends on positions and ids only, whose halves (and halves of halves)
// are the two sides of the cut across the smallest section of the
// assembly, a repeating axis counting twice. Two threads take one half
// each (contact_forces.cpp), so that cut is what their data share.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "particle_order.h"

namespace dem {
namespace {

// Spheres on a cubic lattice of spacing 1 filling nx x ny x nz sites, ids in
// a shuffled order unrelated to the slots.
Particles<3> lattice(int nx, int ny, int nz, unsigned seed) {
  Particles<3> p;
  std::vector<Vec3> sites;
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      for (int k = 0; k < nz; ++k) sites.push_back({i + 0.5, j + 0.5, k + 0.5});
    }
  }
  std::mt19937 random(seed);
  std::shuffle(sites.begin(), sites.end(), random);
  std::vector<std::size_t> ids(sites.size());
  std::iota(ids.begin(), ids.end(), 0);
  std::shuffle(ids.begin(), ids.end(), random);
  for (std::size_t s = 0; s < sites.size(); ++s) {
    p.position.push_back(sites[s]);
    p.radius.push_back(0.5);
    p.id.push_back(ParticleId::from_index(ids[s]));
  }
  return p;
}

Periodic<3> repeating_xy(double lx, double ly) {
  PeriodicDefT<3> def;
  def.axes = {true, true, false};
  def.max = {lx, ly, 0.0};
  return Periodic<3>::from(def);
}

// The largest coordinate along `axis` of the first half of the order and
// the smallest of the second.
std::pair<double, double> halves_along(const Particles<3>& p, const std::vector<Slot>& order, int axis) {
  const std::size_t half = order.size() / 2;
  double first_max = -1e300, second_min = 1e300;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const double x = p.position[static_cast<std::size_t>(order[k])][axis];
    if (k < half) {
      first_max = std::max(first_max, x);
    } else {
      second_min = std::min(second_min, x);
    }
  }
  return {first_max, second_min};
}

TEST(ParticleOrder, IsAPermutationThatFollowsPositionsAndIdsOnly) {
  const Particles<3> p = lattice(20, 20, 14, 1);
  const std::vector<Slot> order = spatial_order(p, repeating_xy(20.0, 20.0), 1.0);
  std::vector<Slot> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<Slot> every(p.size());
  std::iota(every.begin(), every.end(), 0);
  EXPECT_EQ(sorted, every);

  // The same particles in other slots: the same ids in the same order.
  Particles<3> moved = p;
  std::vector<Slot> shuffle(p.size());
  std::iota(shuffle.begin(), shuffle.end(), 0);
  std::mt19937 random(2);
  std::shuffle(shuffle.begin(), shuffle.end(), random);
  for (std::size_t s = 0; s < p.size(); ++s) {
    moved.position[s] = p.position[static_cast<std::size_t>(shuffle[s])];
    moved.id[s] = p.id[static_cast<std::size_t>(shuffle[s])];
  }
  const std::vector<Slot> moved_order = spatial_order(moved, repeating_xy(20.0, 20.0), 1.0);
  for (std::size_t k = 0; k < p.size(); ++k) {
    ASSERT_EQ(moved.id[static_cast<std::size_t>(moved_order[k])], p.id[static_cast<std::size_t>(order[k])]) << k;
  }
}

// A bed periodic in x and y, 20 x 20 wide and 14 high, like the dense
// benchmark's (100 x 100 x 72 radii): a cut across x or y would be made
// twice (at the seam too), 2 x 20 x 14 = 560 against 20 x 20 = 400 across
// z, so the halves are the bottom and the top of the bed.
TEST(ParticleOrder, ARepeatingBedIsCutBetweenBottomAndTop) {
  const Particles<3> p = lattice(20, 20, 14, 3);
  const auto [bottom_top, top_bottom] = halves_along(p, spatial_order(p, repeating_xy(20.0, 20.0), 1.0), 2);
  EXPECT_LE(bottom_top, top_bottom);
  EXPECT_LT(bottom_top, 13.0);
}

// The same bed closed on every side and longer in x: the smallest section
// is across x (20 x 14).
TEST(ParticleOrder, AClosedBoxIsCutAcrossItsLongestSide) {
  const Particles<3> p = lattice(28, 20, 14, 4);
  const auto [left_end, right_start] = halves_along(p, spatial_order(p, Periodic<3>{}, 1.0), 0);
  EXPECT_LE(left_end, right_start);
  EXPECT_LT(left_end, 27.0);
}

}  // namespace
}  // namespace dem
