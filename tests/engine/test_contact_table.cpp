// Contact persistence (BALL's TOL): shear history survives neighbour-list
// rebuilds while a pair stays in contact, and the index gathers in order.
#include <gtest/gtest.h>

#include "contact_table.h"

namespace dem {
namespace {

TEST(ContactTable, RebuildKeepsHistoryOfSurvivingPairs) {
  ContactTable<2> table;
  rebuild_contacts(table, {{0, 1}, {0, 2}, {1, 2}}, {{2, 0}}, 3);
  table.pairs[1].state.shear = 42.0;  // (0, 2)
  table.pairs[1].state.touching = true;
  table.walls[0].state.normal_force = 7.0;
  rebuild_contacts(table, {{0, 2}, {1, 2}, {1, 3}}, {{1, 0}, {2, 0}}, 4);
  ASSERT_EQ(table.pairs.size(), 3u);
  EXPECT_EQ(table.pairs[0].first, 0);
  EXPECT_EQ(table.pairs[0].second, 2);
  EXPECT_EQ(table.pairs[0].state.shear, 42.0);
  EXPECT_EQ(table.pairs[2].state.shear, 0.0);  // new pair (1, 3)
  EXPECT_EQ(table.walls[1].state.normal_force, 7.0);
  EXPECT_EQ(table.walls[0].state.normal_force, 0.0);
  // Particle 2 sees contacts 0 (as second) and 1 (as second), in table order.
  const ContactIndex& index = table.index;
  ASSERT_EQ(index.pair_offsets[3] - index.pair_offsets[2], 2);
  EXPECT_EQ(index.pair_entries[index.pair_offsets[2]], 2 * 0 + 1);
  EXPECT_EQ(index.pair_entries[index.pair_offsets[2] + 1], 2 * 1 + 1);
}

}  // namespace
}  // namespace dem
