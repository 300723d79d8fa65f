// The contact table: history survives neighbour-list rebuilds while a pair
// stays close (BALL's TOL) and survives the particles' re-sorting; the
// blocks of the force pass set aside exactly the rows that cross them.
#include <gtest/gtest.h>

#include "contact_blocks.h"
#include "contact_table.h"

namespace dem {
namespace {

TEST(ContactTable, MergeKeepsTheHistoryOfSurvivingPairs) {
  ContactRows<2> rows;
  rows.columns.normal_force = true;
  merge_rows(rows, {{0, 1}, {0, 2}, {1, 2}});
  rows.shear[1] = 42.0;  // (0, 2)
  rows.flags[1] = kTouching;
  rows.normal_force[1] = 7.0;
  rows.formed_cycle[1] = 12;
  merge_rows(rows, {{0, 2}, {1, 2}, {1, 3}});
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows.first[0], 0);
  EXPECT_EQ(rows.second[0], 2);
  EXPECT_EQ(rows.shear[0], 42.0);
  EXPECT_EQ(rows.normal_force[0], 7.0);
  EXPECT_EQ(rows.formed_cycle[0], 12u);
  EXPECT_TRUE(rows.touching(0));
  EXPECT_EQ(rows.first[2], 1);  // the new pair (1, 3) starts afresh
  EXPECT_EQ(rows.second[2], 3);
  EXPECT_EQ(rows.shear[2], 0.0);
  EXPECT_FALSE(rows.touching(2));
  EXPECT_TRUE(rows.mindlin.empty()) << "columns a world does not use stay empty";
}

TEST(ContactTable, RenamedSlotsKeepHistoryAndOrientation) {
  ContactRows<3> rows;
  merge_rows(rows, {{0, 1}, {0, 2}, {2, 1}});  // (2, 1): the lower id sits in slot 2
  for (std::size_t r = 0; r < 3; ++r) rows.shear[r] = Vec3(static_cast<double>(r) + 1.0, 0.0, 0.0);
  // Slots 0 -> 2, 1 -> 0, 2 -> 1.
  rename_slots(rows, {2, 0, 1}, true);
  ASSERT_EQ(rows.size(), 3u);
  // Sorted by the new keys: (1, 0) was (2, 1), (2, 0) was (0, 1), (2, 1) was (0, 2).
  EXPECT_EQ(rows.first[0], 1);
  EXPECT_EQ(rows.second[0], 0);
  EXPECT_EQ(rows.shear[0].x(), 3.0);
  EXPECT_EQ(rows.first[1], 2);
  EXPECT_EQ(rows.second[1], 0);
  EXPECT_EQ(rows.shear[1].x(), 1.0);
  EXPECT_EQ(rows.shear[2].x(), 2.0);
  // A slot renamed to -1 (a removed particle) drops its rows.
  rename_slots(rows, {0, -1, 1}, true);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows.first[0], 1);  // was (2, 0)
  EXPECT_EQ(rows.second[0], 0);
  EXPECT_EQ(rows.shear[0].x(), 1.0);
}

TEST(ContactBlocks, CrossRowsAreSetAsideInRowOrderForTheirBlock) {
  ContactTable<2> table;
  // Eight particles in four blocks of two: {0, 1}, {2, 3}, {4, 5}, {6, 7}.
  merge_rows(table.pairs, {{0, 1}, {0, 4}, {1, 2}, {2, 3}, {3, 0}, {4, 2}, {5, 4}, {6, 7}, {7, 5}});
  merge_rows(table.walls, {{1, 0}, {4, 0}});
  ContactBlocks<2> blocks;
  plan_blocks(blocks, table, 8, 2);
  ASSERT_EQ(blocks.count(), 4);
  EXPECT_EQ(blocks.pair_begin, (std::vector<std::int32_t>{0, 3, 5, 7, 9}));
  EXPECT_EQ(blocks.wall_begin, (std::vector<std::int32_t>{0, 1, 1, 2, 2}));
  // Rows crossing blocks: 1 (0 -> 4), 2 (1 -> 2), 4 (3 -> 0), 5 (4 -> 2), 8 (7 -> 5).
  EXPECT_EQ(blocks.cross_row, (Column<std::int32_t>{1, 2, 4, 5, 8}));
  EXPECT_EQ(blocks.deferred_begin, (std::vector<std::int32_t>{0, 1, 3, 5, 5}));
  // Block 1 (particles 2, 3) receives rows 2 and 5, block 2 rows 1 and 8, in that order.
  EXPECT_EQ(blocks.deferred_particle, (Column<Slot>{0, 2, 2, 4, 5}));
  EXPECT_EQ(blocks.cross_slot, (Column<std::int32_t>{3, 1, 0, 2, 4}));
}

// Blocks come in powers of two, the nearest to particles / block size, so
// that each is one of the particle order's last halves (particle_order.h).
TEST(ContactBlocks, ComeInPowersOfTwo) {
  const ContactTable<3> table;
  const auto count = [&](std::size_t particles, int block_size) {
    ContactBlocks<3> blocks;
    plan_blocks(blocks, table, particles, block_size);
    return blocks.count();
  };
  EXPECT_EQ(count(1000, 4096), 1);
  EXPECT_EQ(count(10000, 4096), 2);    // 2.4
  EXPECT_EQ(count(100000, 4096), 32);  // 24.4
  EXPECT_EQ(count(1000000, 4096), 256);
  EXPECT_EQ(count(6, 2), 4);  // 3
  EXPECT_EQ(count(1500, 32), 64);
}

// The law of motion writes the pass's side-by-side copies, whole records at
// a time, with streaming stores on large beds and plain ones on small
// (copy_hot_particles); either way they must hold the particles' values to
// the bit, or the pass would compute other forces.
template <int Dim, bool kStream>
void expect_copies_hold_the_particles() {
  Particles<Dim> p;
  const int count = 37;  // not a multiple of any vector width
  for (int i = 0; i < count; ++i) {
    const double a = 0.1 * i - 1.7;
    Vec<Dim> x, v;
    for (int k = 0; k < Dim; ++k) {
      x[k] = a * (k + 1) + 1e-13 * i;
      v[k] = -a / (k + 2);
    }
    p.position.push_back(x);
    p.velocity.push_back(v);
    if constexpr (Dim == 3)
      p.angular_velocity.push_back(Vec3(a, -2.0 * a, 1.0 / (i + 1)));
    else
      p.angular_velocity.push_back(a);
    p.radius.push_back(0.01 + 1e-4 * i);
    p.mass.push_back(1e-3 * (i + 1));
  }
  std::vector<HotPlace<Dim>> place(count);
  std::vector<HotMotion<Dim>> motion(count);
  copy_hot_particles<kStream>(p, place.data(), motion.data(), 0, 5);
  copy_hot_particles<kStream>(p, place.data(), motion.data(), 5, count);
  if (kStream) finish_streaming();
  for (int i = 0; i < count; ++i) {
    EXPECT_EQ(place[i].position, p.position[i]) << i;
    EXPECT_EQ(place[i].radius, p.radius[i]) << i;
    EXPECT_EQ(motion[i].velocity, p.velocity[i]) << i;
    EXPECT_EQ(motion[i].mass, p.mass[i]) << i;
    EXPECT_EQ(motion[i].angular_velocity, p.angular_velocity[i]) << i;
  }
}

TEST(ContactBlocks, StreamedAndStoredCopiesHoldTheParticles) {
  expect_copies_hold_the_particles<3, true>();
  expect_copies_hold_the_particles<3, false>();
  expect_copies_hold_the_particles<2, true>();
  expect_copies_hold_the_particles<2, false>();
}

}  // namespace
}  // namespace dem
