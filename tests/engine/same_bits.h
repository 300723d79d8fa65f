// Comparisons the engine tests share between two worlds that must have
// come out bit for bit the same (two paths through the engine that compute
// one thing).
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>

namespace dem::testing {

// Every particle's position, velocity and spin, and every wall's sums, of
// `a` and `b` equal to the bit; prints the first wall's and the last wall's
// contacts and normal force. Call it through ASSERT_NO_FATAL_FAILURE: a
// particle that differs stops the comparison.
template <typename World>
void expect_same_particles_and_walls(const World& a, const World& b) {
  const auto& pa = a.particles();
  const auto& pb = b.particles();
  for (const auto i : a.particle_ids()) {
    ASSERT_EQ(pa.position[i], pb.position[i]) << "particle " << i;
    ASSERT_EQ(pa.velocity[i], pb.velocity[i]) << "particle " << i;
    ASSERT_EQ(pa.angular_velocity[i], pb.angular_velocity[i]) << "particle " << i;
  }
  const auto walls_a = a.wall_measures(), walls_b = b.wall_measures();
  ASSERT_EQ(walls_a.size(), walls_b.size());
  for (std::size_t k = 0; k < walls_a.size(); ++k) {
    EXPECT_EQ(walls_a[k].force, walls_b[k].force) << "wall " << k;
    EXPECT_EQ(walls_a[k].moment, walls_b[k].moment) << "wall " << k;
    EXPECT_EQ(walls_a[k].normal_force, walls_b[k].normal_force) << "wall " << k;
    EXPECT_EQ(walls_a[k].contacts, walls_b[k].contacts) << "wall " << k;
    EXPECT_EQ(walls_a[k].eccentricity, walls_b[k].eccentricity) << "wall " << k;
    EXPECT_EQ(walls_a[k].point, walls_b[k].point) << "wall " << k;
  }
  const auto& first = walls_a.front();
  const auto& last = walls_a.back();
  std::printf("floor %d contacts at %.6g N, lid %d at %.6g N: same bits\n", first.contacts, first.normal_force,
              last.contacts, last.normal_force);
}

// A world with round particles, walls and the energy budget off runs its
// wall rows through the batched pass (wall_batch.h); the same world with
// the budget on runs them through the general row body (contact_row.h).
// After `cycles` both must hold the same bits, and the first wall (the
// floor) and the last (a lid) must have been touched for it to mean
// anything.
template <typename World, typename Def>
void expect_batched_wall_rows_match_the_general_rows(const Def& plain_def, std::uint64_t cycles) {
  Def budget_def = plain_def;
  budget_def.energy_budget = true;
  World plain(plain_def), budget(budget_def);
  plain.cycle(cycles);
  budget.cycle(cycles);
  ASSERT_NO_FATAL_FAILURE(expect_same_particles_and_walls(plain, budget));
  const auto walls = plain.wall_measures();
  const auto& floor_measure = walls.front();
  const auto& lid_measure = walls.back();
  EXPECT_GT(floor_measure.contacts, 0);
  EXPECT_GT(lid_measure.contacts, 0) << "the lid must reach the particles";
}

}  // namespace dem::testing
