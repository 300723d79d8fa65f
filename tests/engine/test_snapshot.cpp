// Exact restart: a World rebuilt from a snapshot continues bit for bit,
// and one or two threads give the same state.
#include <gtest/gtest.h>

#include "dem/error.h"
#include "dem/packing.h"
#include "dem/world.h"
#include "exact_continuation.h"
#include "model_builders.h"
#include "snapshot_worlds.h"

namespace dem {
namespace {

using testing::expect_exact_continuation;
using testing::settling_box;

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

ContactModelDef hertz(ContactLaw law) {
  ContactModelDef m;
  m.law = law;
  m.hertz.restitution = 0.4;
  return m;
}

TEST(Snapshot, HertzMindlinHistoryCarriesOver) {
  WorldDef def = settling_box();
  for (MaterialDef& m : def.materials) {
    m.youngs_modulus = 1e8;
    m.poisson_ratio = 0.25;
  }
  def.contact_models = {hertz(ContactLaw::kHertzMindlin)};
  expect_exact_continuation(def, 3000, 3000, "discs, Hertz-Mindlin");
}

// Rolling resistance (rolling_resistance.h): the rolling springs' torques
// are history too.
TEST(Snapshot, RollingResistanceCarriesOver) {
  WorldDef def = settling_box();
  def.contact_models[0].rolling = RollingResistanceDef{0.1, 0.3};
  expect_exact_continuation(def, 3000, 3000, "discs, rolling resistance");
  WorldDef3 spheres = testing::sphere_stack(ContactLaw::kLinear);
  spheres.contact_models[0].rolling = RollingResistanceDef{0.05, 0.2};
  expect_exact_continuation(spheres, 400, 400, "spheres with rolling resistance");
}

TEST(Snapshot, SuperquadricSearchesCarryOver) {
  WorldDef def = settling_box();
  def.particles.clear();
  RandomPackingDef packing;
  packing.min = {0.0, 0.0};
  packing.max = {0.3, 0.3};
  packing.sizes = {{0.0, 40, ShapeDefT<2>{0.014, 0.008, 3.0, 0.0}}, {0.0, 50, ShapeDefT<2>{0.009, 0.006, 2.5, 0.0}}};
  packing.seed = 5;
  def.particles = generate_random_packing(packing);
  expect_exact_continuation(def, 1000, 1000, "superquadrics");
}

TEST(Snapshot, EllipsoidSearchesCarryOver) {
  WorldDef3 def;
  def.materials = {MaterialDef{"rock", 2650.0, 0.6, 0.0, 1e8, 0.2}};
  def.contact_models = {hertz(ContactLaw::kHertzLinearTangential)};
  RandomPackingDef3 packing;
  packing.min = {0.0, 0.0, 0.0};
  packing.max = {0.2, 0.2, 0.5};
  packing.sizes = {{0.0, 30, ShapeDefT<3>{{0.03, 0.021, 0.015}, Quaternion::Identity()}}};
  packing.seed = 3;
  def.particles = generate_random_packing(packing);
  auto wall = [](const char* name, Vec3 point, Vec3 u, Vec3 v) {
    WallDef3 w;
    w.name = name;
    w.point = point;
    w.direction = u;
    w.direction2 = v;
    w.h1 = w.k1 = -0.2;
    w.h2 = w.k2 = 0.4;
    return w;
  };
  def.walls = {wall("floor", {0.0, 0.0, 0.0}, Vec3::UnitX(), Vec3::UnitY()),
               wall("x0", {0.0, 0.0, 0.0}, Vec3::UnitY(), Vec3::UnitZ()),
               wall("x1", {0.2, 0.0, 0.0}, Vec3::UnitZ(), Vec3::UnitY()),
               wall("y0", {0.0, 0.0, 0.0}, Vec3::UnitZ(), Vec3::UnitX()),
               wall("y1", {0.0, 0.2, 0.0}, Vec3::UnitX(), Vec3::UnitZ())};
  def.gravity = {0.0, 0.0, -9.81};
  def.time_step_fraction = 0.2;
  expect_exact_continuation(def, 3000, 2000, "ellipsoids");
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
  snap = world.snapshot();
  snap.contacts.push_back(snap.contacts[0]);
  EXPECT_THROW(World{snap}, DefinitionError);
  snap = world.snapshot();
  snap.reference_positions.pop_back();
  EXPECT_THROW(World{snap}, DefinitionError);
}

TEST(Snapshot, ParametersCanChangeBetweenCycles) {
  World world(settling_box());
  world.set_time_step_fraction(0.05);
  EXPECT_DOUBLE_EQ(world.time_step(), 0.05 * world.undamped_critical_time_step());
  EXPECT_THROW(world.set_time_step_fraction(1.5), DefinitionError);
  world.set_friction(MaterialId{0}, 0.9);
  EXPECT_EQ(world.materials()[0].friction, 0.9);
  EXPECT_THROW(world.set_friction(MaterialId{7}, 0.1), DefinitionError);
  EXPECT_THROW(world.set_friction(MaterialId{0}, -1.0), DefinitionError);
  // A restored world keeps the settings it was saved with.
  World restored(world.snapshot());
  EXPECT_EQ(restored.time_step(), world.time_step());
  EXPECT_EQ(restored.materials()[0].friction, 0.9);
}

}  // namespace
}  // namespace dem
