// The health of a step (dem/health.h): a sound run stays healthy; a state
// that is not finite, a step above the critical step, energy appearing
// from nowhere, a particle flung out and particles passing through each
// other are each named.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "dem/health.h"
#include "dem/packing.h"
#include "model_builders.h"

namespace dem {
namespace {

using ::testing::HasSubstr;

// Two rows of three discs in a box of four walls.
WorldDef box() {
  WorldDef def;
  def.materials = {MaterialDef{"disc", 1000.0, 0.5, 0.0}};
  def.contact_models = {testing::linear_model(1.0e6, 1.0e6)};
  LatticeDef lattice;
  lattice.radius = 0.5;
  lattice.origin = {0.5, 0.5};
  lattice.columns = 3;
  lattice.rows = 2;
  lattice.spacing = 1.0;
  def.particles = generate_lattice(lattice);
  def.walls = {WallDef{"bottom", {1.5, 0}, {1, 0}, -5, 5, MaterialId{0}, {}},
               WallDef{"right", {3, 1}, {0, 1}, -5, 5, MaterialId{0}, {}},
               WallDef{"top", {1.5, 2}, {-1, 0}, -5, 5, MaterialId{0}, {}},
               WallDef{"left", {0, 1}, {0, -1}, -5, 5, MaterialId{0}, {}}};
  def.gravity = {0.0, -9.81};
  def.time_step_fraction = 0.1;
  def.threads = 1;
  return def;
}

// Undamped discs bouncing on the floor: gravity's work goes up and down.
TEST(NumericalHealth, ASoundRunStaysHealthy) {
  World world(box());
  HealthMonitor monitor(world);
  for (int i = 0; i < 20; ++i) {
    world.cycle(50);
    const StepHealth health = monitor.assess(world);
    ASSERT_TRUE(health.ok()) << health.message;
    EXPECT_FALSE(monitor.motion_suspect(world));
    EXPECT_EQ(health.cycle, world.cycle_count());
  }
}

// Validation would refuse this stiffness (beyond 1e30) and the step: the
// engine alone takes them.
TEST(NumericalHealth, AStateThatIsNotFiniteIsNamed) {
  WorldDef def = box();
  def.contact_models = {testing::linear_model(1e200, 1e200)};
  def.fixed_time_step = 0.1;
  def.particles[1].position.x() -= 0.3;
  World world(def);
  HealthMonitor monitor(world);
  world.cycle(3);
  const StepHealth health = monitor.assess(world);
  EXPECT_EQ(health.problem, HealthProblem::kNonFinite) << health.message;
  EXPECT_THAT(health.message, HasSubstr("at cycle 3: "));
  EXPECT_THAT(health.message, HasSubstr("reduce the time step"));
}

TEST(NumericalHealth, AStepAboveTheCriticalStepIsNamed) {
  WorldDef def = box();
  def.fixed_time_step = 1.0;
  const World world(def);
  ASSERT_GT(world.time_step(), world.critical_time_step());
  const StepHealth health = HealthMonitor(world).assess(world);
  EXPECT_EQ(health.problem, HealthProblem::kStepAboveCritical);
  EXPECT_THAT(health.message, HasSubstr("exceeds the critical step"));
}

// Within the critical step for one contact, beyond it for a disc pressed
// between two: the energy grows with nothing putting it in.
TEST(NumericalHealth, EnergyFromNowhereIsNamedBeforeItOverflows) {
  WorldDef def = box();
  def.gravity = {0.0, 0.0};
  def.energy_budget = true;
  def.fixed_time_step = 0.98 * World(def).critical_time_step();
  // Squeeze the rows between the walls: every disc starts pressed.
  for (auto& wall : def.walls) wall.point -= 0.02 * (wall.point - Vec2(1.5, 1.0)).normalized();
  World world(def);
  HealthMonitor monitor(world);
  StepHealth health;
  for (int i = 0; i < 500 && health.ok(); ++i) {
    world.cycle(1);
    health = monitor.assess(world);
  }
  EXPECT_EQ(health.problem, HealthProblem::kEnergyGrowth) << health.message;
  EXPECT_THAT(health.message, HasSubstr("J of energy appeared without work done"));
  EXPECT_TRUE(std::isfinite(world.assembly_measures().kinetic_energy));
}

// Without the energy budget no work is booked: discs falling under gravity
// gain kinetic energy that is not energy from nowhere.
TEST(NumericalHealth, AWorldWithoutTheEnergyBudgetIsNotCheckedForEnergyGrowth) {
  WorldDef def = box();
  def.particles.resize(3);  // the bottom row, lifted half a diameter
  for (auto& particle : def.particles) particle.position.y() += 0.5;
  World world(def);
  ASSERT_FALSE(world.energy_budget());
  HealthMonitor monitor(world);
  for (int i = 0; i < 100; ++i) {
    world.cycle(5);
    const StepHealth health = monitor.assess(world);
    ASSERT_TRUE(health.ok()) << health.message;
  }
  EXPECT_GT(world.assembly_measures().kinetic_energy, 0.0);
}

// A blow-up in a world without the energy budget: the particle it flings
// travels several radii a step (the nine discs of
// tests/service/data/blows_up.case.txtpb reach 6). Sound runs move a
// thousandth of a radius (docs/RELIABILITY.md).
TEST(NumericalHealth, AParticleFlungOutIsNamed) {
  WorldDef def = box();
  def.gravity = {0.0, 0.0};
  World probe(def);
  const double speed = 0.6 * def.particles[4].radius / probe.time_step();
  def.particles[4].velocity = {0.0, speed};
  World world(def);
  ASSERT_FALSE(world.energy_budget());
  HealthMonitor monitor(world);
  EXPECT_TRUE(monitor.motion_suspect(world));  // the pass over the particles between assessments sees it too
  const StepHealth health = monitor.assess(world);
  EXPECT_EQ(health.problem, HealthProblem::kRunaway) << health.message;
  EXPECT_THAT(health.message, HasSubstr("particle 4 moves 0.6 of its radius in a step (the limit is 0.5)"));
}

// The constructor's force pass finds the contacts where the particles
// stand (cycle 0), so the overlap is the one placed.
TEST(NumericalHealth, ParticlesPassingThroughEachOtherAreNamed) {
  WorldDef def = box();
  def.particles.resize(2);
  def.particles[1].position = def.particles[0].position + Vec2(0.6, 0.0);  // 0.4 deep: 80% of a radius
  const World world(def);
  const StepHealth health = HealthMonitor(world).assess(world);
  EXPECT_EQ(health.problem, HealthProblem::kOverlap) << health.message;
  EXPECT_THAT(health.message, HasSubstr("the contact of particle 0 and particle 1 overlaps 0.8"));
}

}  // namespace
}  // namespace dem
