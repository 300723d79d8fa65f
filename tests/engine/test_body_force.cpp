// Randall's (1989) centripetal gravity field, 6.4.2: every particle pulled
// towards a centre at a given acceleration ("all the particles would
// travel together towards the centre"), its work booked with gravity's,
// switched on and off by stages, in the snapshot and the state hash; and
// the errors that name a bad field.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "dem/error.h"
#include "dem/packing.h"
#include "dem/programme.h"
#include "dem/world.h"
#include "exact_continuation.h"
#include "model_builders.h"

namespace dem {
namespace {

const Vec2 kCentre{0.1, 0.1};

// Discs scattered over a 0.2 m square with no walls, no gravity, the
// centripetal field towards the square's centre at 50 m/s^2; dashpots and
// friction at the contacts, a little global damping.
WorldDef scattered_discs() {
  WorldDef def;
  def.materials = {MaterialDef{"disc", 2650.0, 0.3, 0.0}};
  def.contact_models = {testing::linear_model(1e6, 1e6)};
  def.contact_models[0].law = ContactLaw::kLinearRestitution;
  def.contact_models[0].restitution = 0.3;
  RandomPackingDef packing;
  packing.min = {0.0, 0.0};
  packing.max = {0.2, 0.2};
  packing.sizes = {{0.008, 40}, {0.006, 60}};
  packing.seed = 8;
  def.particles = generate_random_packing(packing);
  def.centripetal_gravity = CentripetalGravity{kCentre, 50.0};
  def.damping.global_alpha = 2.0;
  def.fixed_time_step = 1e-4;
  def.energy_budget = true;
  def.threads = 1;
  return def;
}

// A lone disc falls along its radius as under uniform gravity: the
// central differences give x_n = x_0 - a dt^2 n (n + 1) / 2 towards the
// centre, exactly.
TEST(CentripetalGravity, ALoneDiscFallsTowardsTheCentre) {
  WorldDef def = scattered_discs();
  def.particles = {ParticleDef{kCentre + Vec2{0.06, 0.08}, 0.005, MaterialId{0}, {0.0, 0.0}, 0.0}};
  def.damping = {};
  World world(def);
  const int n = 400;
  world.cycle(n);
  const double dt = world.time_step();
  const double fallen = 50.0 * dt * dt * n * (n + 1) / 2.0;
  const Vec2 x = world.particles().position[ParticleId{0}];
  std::printf("after %d steps: %.12f m from the centre (0.1 - %.12f expected), off the radius by %.2e m\n", n,
              (x - kCentre).norm(), fallen, std::abs((x - kCentre).x() * 0.08 - (x - kCentre).y() * 0.06));
  EXPECT_NEAR((x - kCentre).norm(), 0.1 - fallen, 1e-14);
  EXPECT_NEAR((x - kCentre).x() * 0.08, (x - kCentre).y() * 0.06, 1e-15);
}

// The discs gather into a compact assembly around the centre (Fig. 6.4's
// state); the field's work is what the springs hold and the dampers took,
// up to the integration error, which falls as dt^2 (a field's work left
// out would not fall).
TEST(CentripetalGravity, ItsWorkClosesTheEnergyBudget) {
  double residual[2] = {0.0, 0.0};
  for (const int k : {0, 1}) {
    WorldDef def = scattered_discs();
    def.fixed_time_step = k == 0 ? 1e-4 : 5e-5;
    World world(def);
    world.cycle(k == 0 ? 20000 : 40000);
    const EnergyBudget e = world.assembly_measures().energy;
    double farthest = 0.0;
    for (const Vec2& x : world.particles().position) farthest = std::max(farthest, (x - kCentre).norm());
    residual[k] = std::abs(e.residual()) / e.gravity_work;
    std::printf(
        "dt %.0e s, after 2 s: %zu contacts, farthest centre %.4f m; body-force work %.6e J, kinetic %.3e, "
        "strain %.3e, dashpots %.3e, friction %.3e, global damping %.3e J; residual %.3e J (%.2e of the "
        "work)\n",
        def.fixed_time_step, world.contacts().size(), farthest, e.gravity_work, e.kinetic, e.strain, e.contact_damping,
        e.friction, e.global_damping, e.residual(), residual[k]);
    EXPECT_GT(world.contacts().size(), 150u);  // a compact assembly: over 1.5 contacts per disc
    EXPECT_LT(farthest, 0.1);                  // all gathered in from the corners
    EXPECT_GT(e.gravity_work, 0.0);
  }
  EXPECT_LT(residual[0], 1e-2);
  EXPECT_NEAR(residual[0] / residual[1], 4.0, 1.0);  // second order in dt
}

TEST(CentripetalGravity, RestartAndThreadsStayExact) {
  testing::expect_exact_continuation(scattered_discs(), 4000, 4000, "centripetal compaction");
}

// Randall's sequence: the field set, the system cycled, then the field
// removed (and gravity with it) by the next stage's body force.
TEST(CentripetalGravity, StagesSwitchTheField) {
  WorldDef def = scattered_discs();
  def.centripetal_gravity.reset();
  World world(def);
  const std::uint64_t before = world.state_hash();
  StageDef compact;
  compact.body_force = BodyForce{{0.0, 0.0}, CentripetalGravity{kCentre, 50.0}};
  compact.cycles = 2000;
  run_stage(world, compact);
  ASSERT_TRUE(world.centripetal_gravity().has_value());
  EXPECT_EQ(world.centripetal_gravity()->acceleration, 50.0);
  EXPECT_NE(world.state_hash(), before);
  StageDef release;
  release.body_force = BodyForce{};
  release.cycles = 10;
  run_stage(world, release);
  EXPECT_FALSE(world.centripetal_gravity().has_value());
  EXPECT_EQ(world.gravity(), Vec2::Zero());
  // A stage without a body force leaves the field as it was.
  StageDef other;
  other.cycles = 10;
  world.set_body_force(BodyForce{{0.0, -9.81}, CentripetalGravity{kCentre, 5.0}});
  run_stage(world, other);
  EXPECT_EQ(world.centripetal_gravity()->acceleration, 5.0);
  EXPECT_EQ(world.gravity().y(), -9.81);
}

// The field is in the state hash and in the snapshot.
TEST(CentripetalGravity, TheHashAndTheSnapshotCarryIt) {
  WorldDef def = scattered_discs();
  World with(def);
  def.centripetal_gravity->acceleration = 50.000001;
  World stronger(def);
  EXPECT_NE(with.state_hash(), stronger.state_hash());
  World restored(with.snapshot());
  ASSERT_TRUE(restored.centripetal_gravity().has_value());
  EXPECT_EQ(restored.centripetal_gravity()->centre, kCentre);
  EXPECT_EQ(restored.centripetal_gravity()->acceleration, 50.0);
  EXPECT_EQ(restored.state_hash(), with.state_hash());
}

std::string body_force_error(const BodyForce& body_force) {
  World world(scattered_discs());
  const std::uint64_t before = world.state_hash();
  try {
    world.set_body_force(body_force);
  } catch (const DefinitionError& e) {
    EXPECT_EQ(world.state_hash(), before) << "a refused body force must change nothing";
    return e.what();
  }
  return "";
}

TEST(CentripetalGravity, BadFieldsNameTheField) {
  EXPECT_EQ(body_force_error(BodyForce{{0.0, 0.0}, CentripetalGravity{kCentre, -1.0}}),
            "centripetal gravity: acceleration must be >= 0");
  EXPECT_EQ(body_force_error(BodyForce{{0.0, 0.0}, CentripetalGravity{{NAN, 0.0}, 1.0}}),
            "centripetal gravity: centre must be finite");
  EXPECT_EQ(body_force_error(BodyForce{{INFINITY, 0.0}, std::nullopt}), "world: gravity must be finite");
  WorldDef def = scattered_discs();
  def.centripetal_gravity->acceleration = -2.0;
  EXPECT_THROW(World{def}, DefinitionError);
}

}  // namespace
}  // namespace dem
