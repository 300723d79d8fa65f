// Exact restart: a World rebuilt from a snapshot continues bit for bit.
#include <gtest/gtest.h>

#include "dem/error.h"
#include "dem/packing.h"
#include "dem/world.h"
#include "model_builders.h"

namespace dem {
namespace {

// Discs settling into a box whose lid is a servo: contact history, sliding,
// wall motion and servo state all matter for the continuation.
WorldDef settling_box() {
  WorldDef def;
  def.materials = {MaterialDef{"disc", 2650.0, 0.4, 0.0}, MaterialDef{"wall", 1.0, 0.2, 0.0}};
  def.contact_models = {testing::linear_model(1.0e6, 0.7e6)};
  RandomPackingDef packing;
  packing.min = {0.0, 0.0};
  packing.max = {0.3, 0.3};
  packing.sizes = {{0.012, 40}, {0.008, 60}};
  packing.seed = 11;
  def.particles = generate_random_packing(packing);
  def.walls = {WallDef{"bottom", {0.15, 0.0}, {1, 0}, -0.2, 0.2, 1, {}},
               WallDef{"right", {0.3, 0.15}, {0, 1}, -0.2, 0.2, 1, {}},
               WallDef{"top", {0.15, 0.3}, {-1, 0}, -0.2, 0.2, 1, {}},
               WallDef{"left", {0.0, 0.15}, {0, -1}, -0.2, 0.2, 1, {}}};
  def.walls[2].motion.servo = ServoDef{200.0, 1e-3, 0.05};
  def.walls[3].motion.velocity = {0.001, 0.0};
  def.gravity = {0.0, -9.81};
  def.damping = {1e-4, 0.5};
  return def;
}

TEST(Snapshot, ContinuationIsBitIdentical) {
  World original(settling_box());
  original.cycle(3000);
  const WorldSnapshot snap = original.snapshot();
  World restored(snap);
  EXPECT_EQ(restored.state_hash(), original.state_hash());
  EXPECT_EQ(restored.cycle_count(), original.cycle_count());
  EXPECT_EQ(restored.contacts().size(), original.contacts().size());
  EXPECT_EQ(restored.wall_measures()[2].normal_force, original.wall_measures()[2].normal_force);
  EXPECT_EQ(restored.assembly_measures().out_of_balance, original.assembly_measures().out_of_balance);
  original.cycle(2000);
  restored.cycle(2000);
  std::printf("after 3000 + 2000 cycles: original %016llx, restored %016llx, %zu contacts\n",
              static_cast<unsigned long long>(original.state_hash()),
              static_cast<unsigned long long>(restored.state_hash()), original.contacts().size());
  EXPECT_GT(original.contacts().size(), 100u);
  EXPECT_EQ(restored.state_hash(), original.state_hash());
}

TEST(Snapshot, InconsistentSnapshotIsRefused) {
  World world(settling_box());
  world.cycle(500);
  WorldSnapshot snap = world.snapshot();
  snap.rotation.pop_back();
  EXPECT_THROW(World{snap}, DefinitionError);
  snap = world.snapshot();
  ASSERT_FALSE(snap.contacts.empty());
  snap.contacts[0].first = 100000;
  EXPECT_THROW(World{snap}, DefinitionError);
  snap = world.snapshot();
  snap.contacts[0].second = snap.contacts[0].first;  // a contact with itself
  EXPECT_THROW(World{snap}, DefinitionError);
}

TEST(Snapshot, ParametersCanChangeBetweenCycles) {
  World world(settling_box());
  world.set_time_step_fraction(0.05);
  EXPECT_DOUBLE_EQ(world.time_step(), 0.05 * world.critical_time_step());
  EXPECT_THROW(world.set_time_step_fraction(1.5), DefinitionError);
  world.set_friction(0, 0.9);
  EXPECT_EQ(world.materials()[0].friction, 0.9);
  EXPECT_THROW(world.set_friction(7, 0.1), DefinitionError);
  EXPECT_THROW(world.set_friction(0, -1.0), DefinitionError);
  // A restored world keeps the settings it was saved with.
  World restored(world.snapshot());
  EXPECT_EQ(restored.time_step(), world.time_step());
  EXPECT_EQ(restored.materials()[0].friction, 0.9);
}

}  // namespace
}  // namespace dem
