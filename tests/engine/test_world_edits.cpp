// Sample preparation (Miyata et al. 2002, 3.1): trimming the surface,
// placing a loading plate on the sample, loading it to a stress.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "dem/error.h"
#include "dem/packing.h"
#include "dem/programme.h"
#include "dem/world.h"
#include "model_builders.h"

namespace dem {
namespace {

// Discs settled under gravity in a box 1 m wide; a plate waits above.
World settled_box() {
  WorldDef def;
  def.materials = {MaterialDef{"rock", 1650.0, 0.51, 0.0}};
  ContactModelDef model = testing::linear_model(1e7, 1e7);
  model.law = ContactLaw::kLinearRestitution;
  model.restitution = 0.3;
  def.contact_models = {model};
  RandomPackingDef packing;
  packing.min = {0.0, 0.0};
  packing.max = {1.0, 1.8};
  packing.sizes = {{0.03, 150}, {0.02, 150}};
  packing.seed = 5;
  def.particles = generate_random_packing(packing);
  def.walls = {WallDef{"bottom", {0.5, 0.0}, {1, 0}, -0.5, 0.5, MaterialId{0}, {}},
               WallDef{"right", {1.0, 0.0}, {0, 1}, 0.0, 3.0, MaterialId{0}, {}},
               WallDef{"left", {0.0, 3.0}, {0, -1}, 0.0, 3.0, MaterialId{0}, {}},
               WallDef{"plate", {0.5, 2.5}, {-1, 0}, -0.5, 0.5, MaterialId{0}, {}}};
  def.gravity = {0.0, -9.81};
  def.energy_budget = true;
  def.damping.local_alpha = 0.3;
  World world(def);
  StageDef settle;
  settle.cycles = 200000;
  settle.until.kinetic_energy_below = 1e-6;
  settle.until.check_interval = 500;
  EXPECT_TRUE(run_stage(world, settle).condition_met);
  return world;
}

TEST(WorldEdits, TrimmingRemovesTheTopAndKeepsTheRest) {
  World world = settled_box();
  const int before = world.particle_count();
  // Pick a surviving contact to follow through the trim.
  const auto contacts = world.contacts();
  ContactRecord kept{};
  for (const ContactRecord& c : contacts) {
    if (c.second_particle != kInvalidId && world.particles().position[c.first].y() < 0.2 &&
        world.particles().position[c.second_particle].y() < 0.2) {
      kept = c;
      break;
    }
  }
  ASSERT_NE(kept.first, kInvalidId);
  const Vec2 kept_first = world.particles().position[kept.first];
  const Vec2 kept_second = world.particles().position[kept.second_particle];

  StageDef trim;
  trim.trim = TrimDef{0.4, 0.05, 0.5};  // a rough surface, Miyata eq. 60
  trim.cycles = 0;
  run_stage(world, trim);
  const auto p = world.particles();
  for (const ParticleId i : world.particle_ids()) {
    EXPECT_LE(p.position[i].y(), 0.4 + 0.05 * std::sin(2.0 * std::numbers::pi * p.position[i].x() / 0.5) + 1e-15);
  }
  std::printf("trimmed %d of %d particles\n", before - world.particle_count(), before);
  EXPECT_LT(world.particle_count(), before);
  // The followed contact survives with its history under the same ids.
  bool found = false;
  for (const ContactRecord& c : world.contacts()) {
    if (c.first != kept.first || c.second_particle != kept.second_particle) continue;
    EXPECT_EQ(p.position[c.first], kept_first);
    EXPECT_EQ(p.position[c.second_particle], kept_second);
    EXPECT_EQ(c.normal_force, kept.normal_force);
    EXPECT_EQ(c.shear_force, kept.shear_force);
    EXPECT_EQ(c.formed_cycle, kept.formed_cycle);
    found = true;
  }
  EXPECT_TRUE(found);
  world.cycle(2000);
  const EnergyBudget e = world.assembly_measures().energy;
  std::printf("energy: gravity %.4e, removed %.3e, residual %.2e (%.3f%%)\n", e.gravity_work, e.removed, e.residual(),
              100.0 * e.residual() / e.gravity_work);
  EXPECT_GT(e.removed, 0.0);
  EXPECT_LT(std::abs(e.residual()), 0.01 * e.gravity_work);
}

TEST(WorldEdits, PlateIsPlacedOnTheSampleAndLoadedToAStress) {
  World world = settled_box();
  const WallId plate = world.find_wall("plate");
  StageDef place;
  place.place_wall = PlaceWallDef{plate, 0.001};
  place.cycles = 0;
  run_stage(world, place);
  double top = 0.0;
  const auto p = world.particles();
  for (int i = 0; i < world.particle_count(); ++i)
    top = std::max(top, p.position[ParticleId::from_index(i)].y() + p.radius[ParticleId::from_index(i)]);
  EXPECT_NEAR(world.wall(plate).point.y(), top + 0.001, 1e-12);
  EXPECT_EQ(world.wall_settlement(plate), 0.0);

  StageDef load;
  WallMotion down;
  down.velocity = {0.0, -0.01};
  load.wall_motions = {{plate, down}};
  load.cycles = 2000000;
  load.until.wall_stress_above = WallThreshold{plate, 20e3};  // 20 kPa over the plate's 1 m (unit depth)
  load.until.check_interval = 10;
  const StageResult result = run_stage(world, load);
  const double stress = world.wall_measures()[plate.index()].normal_force / world.wall_area(plate);
  std::printf("20 kPa reached after %llu cycles: stress %.1f Pa, settlement %.5f m\n",
              static_cast<unsigned long long>(result.cycles_run), stress, world.wall_settlement(plate));
  EXPECT_TRUE(result.condition_met);
  EXPECT_GE(stress, 20e3);
  const double expected = 0.01 * world.time_step() * static_cast<double>(result.cycles_run);
  EXPECT_NEAR(world.wall_settlement(plate), expected, 1e-9 * expected);  // round-off over the steps
  // Contacts on the plate formed after it was placed.
  for (const ContactRecord& c : world.contacts()) {
    if (c.second_wall == plate) {
      EXPECT_GT(c.formed_cycle, world.cycle_count() - result.cycles_run);
    }
  }
}

// Ids stay with their particles (LIGGGHTS' atom ids, PFC's ball ids): a
// trim leaves the survivors' ids, and the removed ones' name nothing.
TEST(WorldEdits, TrimKeepsEveryOtherParticlesId) {
  World world = settled_box();
  const int before = world.particle_count();
  std::vector<Vec2> position;
  for (const ParticleId id : world.particle_ids()) position.push_back(world.particles().position[id]);
  const std::vector<ParticleId> gone{ParticleId{3}, ParticleId{10}, ParticleId{before - 1}};
  world.remove_particles(gone);
  EXPECT_EQ(world.particle_count(), before - 3);
  EXPECT_EQ(world.particle_id_count(), before);  // ids are not reused
  ASSERT_EQ(world.particle_ids().size(), static_cast<std::size_t>(before - 3));
  int checked = 0;
  for (const ParticleId id : world.particle_ids()) {
    EXPECT_TRUE(id != gone[0] && id != gone[1] && id != gone[2]) << id;
    // Nothing moved: the id still reads the particle it named before.
    EXPECT_EQ(world.particles().position[id], position[id.index()]) << id;
    ++checked;
  }
  EXPECT_EQ(checked, before - 3);
  for (const ContactRecord& c : world.contacts()) {
    EXPECT_TRUE(world.has_particle(c.first)) << c.first;
    if (c.second_particle != kInvalidId) {
      EXPECT_TRUE(world.has_particle(c.second_particle)) << c.second_particle;
    }
  }
  EXPECT_FALSE(world.has_particle(ParticleId{10}));
  EXPECT_TRUE(world.has_particle(ParticleId{11}));
  EXPECT_EQ(world.missing_particle(ParticleId{10}), "particle 10 was removed");
  EXPECT_EQ(world.missing_particle(ParticleId{before}), "no particle " + std::to_string(before));
  EXPECT_EQ(world.missing_particle(ParticleId{11}), std::nullopt);
  EXPECT_FALSE(world.contact_between(ParticleId{10}, ParticleId{11}).has_value());
  // The hash of the state is unchanged by the ids' gaps: a copy through
  // the snapshot continues bit for bit, with the same ids.
  World restored(world.snapshot());
  EXPECT_EQ(std::vector<ParticleId>(restored.particle_ids().begin(), restored.particle_ids().end()),
            std::vector<ParticleId>(world.particle_ids().begin(), world.particle_ids().end()));
  EXPECT_EQ(restored.missing_particle(ParticleId{before - 1}),
            "particle " + std::to_string(before - 1) + " was removed");
  EXPECT_EQ(restored.state_hash(), world.state_hash());
  world.cycle(300);
  restored.cycle(300);
  std::printf("after the trim and 300 cycles: original %016llx, restored %016llx\n",
              static_cast<unsigned long long>(world.state_hash()),
              static_cast<unsigned long long>(restored.state_hash()));
  EXPECT_EQ(restored.state_hash(), world.state_hash());
}

TEST(WorldEdits, AStaleIdIsAnErrorAndNothingIsRemoved) {
  World world = settled_box();
  const int before = world.particle_count();
  world.remove_particles(std::vector<ParticleId>{ParticleId{7}});
  const std::uint64_t hash = world.state_hash();
  try {
    world.remove_particles(std::vector<ParticleId>{ParticleId{8}, ParticleId{7}});
    FAIL() << "a removed id was accepted";
  } catch (const DefinitionError& e) {
    EXPECT_STREQ(e.what(), "remove particles: particle 7 was removed");
  }
  // Not half-applied: particle 8, named before the stale id, is still there.
  EXPECT_TRUE(world.has_particle(ParticleId{8}));
  EXPECT_EQ(world.particle_count(), before - 1);
  EXPECT_EQ(world.state_hash(), hash);
  try {
    world.remove_particles(std::vector<ParticleId>{ParticleId{before + 5}});
    FAIL() << "an unknown id was accepted";
  } catch (const DefinitionError& e) {
    EXPECT_STREQ(e.what(), ("remove particles: no particle " + std::to_string(before + 5)).c_str());
  }
}

// The message a call fails with, or "" when it does not throw.
template <typename Call>
std::string refusal(Call&& call) {
  try {
    call();
  } catch (const DefinitionError& e) {
    return e.what();
  }
  return "";
}

TEST(WorldEdits, BadIdsAreRefused) {
  World world = settled_box();
  const std::vector<ParticleId> bad{ParticleId{world.particle_count()}};
  EXPECT_THROW(world.remove_particles(bad), DefinitionError);
  EXPECT_THROW(world.place_wall(WallId{9}, Vec2::Zero()), DefinitionError);
}

// Every edit that names a wall checks its id through missing_wall, so they
// fail alike; a removed wall keeps its id.
TEST(WorldEdits, AWallIdIsCheckedInOnePlace) {
  WorldDef def;
  def.materials = {MaterialDef{"rock", 1650.0, 0.51, 0.0}};
  def.contact_models = {testing::linear_model(1e7, 1e7)};
  def.particles = {ParticleDef{{0.5, 0.5}, 0.05, MaterialId{0}}};
  def.walls = {WallDef{"bottom", {0.5, 0.0}, {1, 0}, -0.5, 0.5, MaterialId{0}, {}},
               WallDef{"right", {1.0, 0.0}, {0, 1}, 0.0, 1.0, MaterialId{0}, {}},
               WallDef{"top", {0.5, 1.0}, {-1, 0}, -0.5, 0.5, MaterialId{0}, {}},
               WallDef{"left", {0.0, 1.0}, {0, -1}, 0.0, 1.0, MaterialId{0}, {}}};
  World world(def);
  EXPECT_EQ(world.missing_wall(WallId{3}), std::nullopt);
  EXPECT_EQ(world.missing_wall(WallId{4}), "no wall 4");
  EXPECT_EQ(world.missing_wall(kInvalidId), "no wall -1");
  EXPECT_EQ(refusal([&] { world.place_wall(WallId{4}, Vec2::Zero()); }), "place wall: no wall 4");
  EXPECT_EQ(refusal([&] { world.remove_wall(kInvalidId); }), "remove wall: no wall -1");
  BoxControlT<2> box;
  box.axes[0] = BoxAxisDef{WallId{3}, WallId{1}};
  box.axes[1] = BoxAxisDef{WallId{0}, WallId{7}};
  EXPECT_EQ(refusal([&] { world.set_box_control(box); }), "box control: axes[1] (y).upper: no wall 7");
  world.remove_wall(WallId{2});
  EXPECT_EQ(world.missing_wall(WallId{2}), std::nullopt);
  EXPECT_EQ(world.wall(WallId{2}).name, "top");
  EXPECT_TRUE(world.wall(WallId{2}).removed);
}

}  // namespace
}  // namespace dem
