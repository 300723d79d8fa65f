// The cell grid of the broad phase and the particle order: every particle
// in a cell of the grid, also when some have blown up. Found by the
// snapshot fuzz target: a restored state whose particles reached NaN within
// three cycles made the grid's extent NaN, and converting it to a cell
// count was undefined behaviour (tests/fuzz/regressions/snapshot).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "broad_phase.h"
#include "cell_grid.h"

namespace dem {
namespace {

Particles<2> particles_at(const std::vector<Vec2>& positions) {
  Particles<2> p;
  p.position.assign(positions.begin(), positions.end());
  return p;
}

// The grid is consistent: every particle once, in a cell that exists.
void expect_whole(const CellGrid<2>& grid, std::size_t particles) {
  const std::int64_t cells = grid.counts[0] * grid.counts[1];
  ASSERT_GE(grid.counts[0], 1);
  ASSERT_GE(grid.counts[1], 1);
  ASSERT_EQ(grid.cell_start.size(), static_cast<std::size_t>(cells) + 1);
  EXPECT_EQ(grid.cell_start.back(), static_cast<std::int32_t>(particles));
  std::vector<int> seen(particles, 0);
  for (const std::int32_t i : grid.cell_particles) ++seen[static_cast<std::size_t>(i)];
  EXPECT_EQ(seen, std::vector<int>(particles, 1));
}

TEST(CellGrid, ParticlesAreInTheCellsOfTheirPositions) {
  const CellGrid<2> grid = build_grid(particles_at({{0.0, 0.0}, {2.5, 0.5}, {0.5, 3.9}}), Periodic<2>{}, 1.0);
  EXPECT_EQ(grid.counts[0], 3);
  EXPECT_EQ(grid.counts[1], 4);
  expect_whole(grid, 3);
  EXPECT_EQ(grid.cell_of({2.5, 0.5}), (CellGrid<2>::Cell{2, 0}));
  EXPECT_EQ(grid.cell_of({-7.0, 99.0}), (CellGrid<2>::Cell{0, 3}));  // clamped to the grid
}

TEST(CellGrid, PositionsThatBlewUpLandAtTheEdge) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const CellGrid<2> grid =
      build_grid(particles_at({{0.0, 0.0}, {nan, 1.0}, {2.5, inf}, {1.0, 1.0}, {-inf, nan}}), Periodic<2>{}, 1.0);
  // The finite ones span the grid, as without the others.
  EXPECT_EQ(grid.counts[0], 2);
  EXPECT_EQ(grid.counts[1], 2);
  expect_whole(grid, 5);
  EXPECT_EQ(grid.cell_of({nan, 1.0}), (CellGrid<2>::Cell{0, 1}));
  EXPECT_EQ(grid.cell_of({2.5, inf}), (CellGrid<2>::Cell{1, 1}));
  // Finite but so far apart that the extent overflows: one cell.
  const CellGrid<2> far = build_grid(particles_at({{-1e308, 0.0}, {1e308, 0.0}}), Periodic<2>{}, 1.0);
  expect_whole(far, 2);
  EXPECT_EQ(far.counts[0], 1);
  // Nothing finite at all.
  expect_whole(build_grid(particles_at({{nan, nan}, {inf, -inf}}), Periodic<2>{}, 1.0), 2);
}

// The broad phase's pairs equal a brute-force search's, keyed and ordered as
// the contact table's rows (first: the lower id's slot), for any thread
// count: ids in no relation to slots, radii of several sizes, one periodic
// axis with two cells (neighbours coincide), one with many, one closed.
TEST(CellGrid, BroadPhaseFindsEveryPairOnce) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Vec3 box{0.05, 0.4, 0.3};
  Particles<3> p;
  const int n = 3000;
  std::vector<int> ids(n);
  for (int k = 0; k < n; ++k) ids[k] = k;
  std::shuffle(ids.begin(), ids.end(), random);
  for (int k = 0; k < n; ++k) {
    p.position.push_back(Vec3{unit(random), unit(random), unit(random)}.cwiseProduct(box));
    p.radius.push_back(0.004 + 0.004 * unit(random));
    p.id.push_back(ParticleId::from_index(static_cast<std::size_t>(ids[k])));
  }
  PeriodicDefT<3> def;
  def.axes = {true, true, false};
  def.max = {box.x(), box.y(), 0.0};
  const Periodic<3> periodic = Periodic<3>::from(def);
  const double tolerance = 0.002;
  std::vector<ContactKey> expected;
  for (Slot i = 0; i < n; ++i) {
    for (Slot j = 0; j < n; ++j) {
      if (!(p.id[i] < p.id[j])) continue;
      if (periodic.separation(p.position[i], p.position[j]).norm() - p.radius[i] - p.radius[j] < tolerance) {
        expected.push_back({i, j});
      }
    }
  }
  std::sort(expected.begin(), expected.end());
  ASSERT_GT(expected.size(), static_cast<std::size_t>(n));
  EXPECT_EQ(find_pair_keys(p, periodic, tolerance, 1), expected);
  EXPECT_EQ(find_pair_keys(p, periodic, tolerance, 2), expected);
}

}  // namespace
}  // namespace dem
