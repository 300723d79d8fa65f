// Superquadric particles in a world (Miyata et al. 2002, section 2.3).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dem/packing.h"
#include "dem/world.h"
#include "model_builders.h"

namespace dem {
namespace {

// A 3 x 3 array of discs compressed by four walls (the nine-disc set-up),
// as discs or as superquadrics with n = 2 and a = b = R.
WorldDef nine(bool superquadric) {
  WorldDef def;
  def.materials = {MaterialDef{"disc", 1000.0, 0.5, 0.0}};
  def.contact_models = {testing::linear_model(1.35e9, 1.0e9)};
  LatticeDef lattice;
  lattice.radius = 50.0;
  lattice.origin = {50.0, 50.0};
  lattice.columns = lattice.rows = 3;
  lattice.spacing = 100.0;
  def.particles = generate_lattice(lattice);
  for (ParticleDef& p : def.particles) {
    if (superquadric) p.shape = ShapeDefT<2>{50.0, 50.0, 2.0, 0.0};
  }
  def.walls = {WallDef{"bottom", {150, 0}, {1, 0}, -200, 200, MaterialId{0}, {}},
               WallDef{"right", {300, 150}, {0, 1}, -200, 200, MaterialId{0}, {}},
               WallDef{"top", {150, 300}, {-1, 0}, -200, 200, MaterialId{0}, {}},
               WallDef{"left", {0, 150}, {0, -1}, -200, 200, MaterialId{0}, {}}};
  def.walls[0].motion.velocity = {0.0, 12.0};
  def.walls[1].motion.velocity = {-12.0, 0.0};
  def.walls[2].motion.velocity = {0.0, -12.0};
  def.walls[3].motion.velocity = {12.0, 0.0};
  def.fixed_time_step = 0.01;
  return def;
}

TEST(SuperquadricWorld, ExponentTwoWithEqualAxesReproducesDiscs) {
  World discs(nine(false)), superquadrics(nine(true));
  EXPECT_DOUBLE_EQ(superquadrics.particles().mass[ParticleId{4}], discs.particles().mass[ParticleId{4}]);
  EXPECT_NEAR(superquadrics.critical_time_step(), discs.critical_time_step(), 1e-12);
  discs.cycle(40);
  superquadrics.cycle(40);
  double worst = 0.0;
  for (std::int32_t a = 0; a < 9; ++a) {
    for (std::int32_t b = a + 1; b < 9; ++b) {
      const auto c = discs.contact_between(ParticleId{a}, ParticleId{b});
      const auto s = superquadrics.contact_between(ParticleId{a}, ParticleId{b});
      ASSERT_EQ(c.has_value(), s.has_value()) << a << "-" << b;
      if (c) worst = std::max(worst, std::abs(s->normal_force - c->normal_force) / c->normal_force);
    }
  }
  const auto wd = discs.wall_measures(), ws = superquadrics.wall_measures();
  for (int w = 0; w < 4; ++w) worst = std::max(worst, std::abs(ws[w].normal_force / wd[w].normal_force - 1.0));
  std::printf("largest relative difference of a contact or wall force after 40 cycles: %.2e\n", worst);
  EXPECT_LT(worst, 1e-6);
}

TEST(SuperquadricWorld, ElongatedParticleComesToRestOnItsLongSide) {
  WorldDef def;
  def.materials = {MaterialDef{"rock", 1650.0, 0.51, 0.0}};
  ContactModelDef model = testing::linear_model(1e7, 1e7);
  model.law = ContactLaw::kLinearRestitution;
  model.restitution = 0.3;
  def.contact_models = {model};
  // Miyata's Table 1 particle, a = 19.5 cm, b = 9.76 cm, n = 4, dropped
  // tilted by 30 degrees from 0.35 m above the floor.
  ParticleDef rock;
  rock.position = {0.0, 0.35};
  rock.shape = ShapeDefT<2>{0.195, 0.0976, 4.0, std::numbers::pi / 6.0};
  def.particles = {rock};
  def.walls = {WallDef{"floor", {0.0, 0.0}, {1.0, 0.0}, -5.0, 5.0, MaterialId{0}, {}}};
  def.gravity = {0.0, -9.81};
  def.damping.local_alpha = 0.2;
  def.time_step_fraction = 0.1;
  World world(def);
  world.cycle(60000);
  const auto p = world.particles();
  const double weight = 9.81 * p.mass[ParticleId{0}];
  const WallMeasure floor = world.wall_measures()[0];
  // Resting on a long side: the centre is b above the floor (less the
  // spring's compression) and the angle a multiple of pi.
  const double turns = p.rotation[ParticleId{0}] / std::numbers::pi;
  std::printf("at rest: centre height %.5f m (b = 0.0976), angle %.4f pi, floor %.6f N of weight %.6f N, %d contacts\n",
              p.position[ParticleId{0}].y(), turns, floor.normal_force, weight, floor.contacts);
  EXPECT_NEAR(p.position[ParticleId{0}].y(), 0.0976, 2e-3);
  EXPECT_NEAR(turns, std::round(turns), 1e-3);
  // A single contact at the support point: the last rocking dies slowly.
  EXPECT_NEAR(floor.normal_force, weight, 1e-4 * weight);
  std::printf("kinetic energy %.3e J\n", world.assembly_measures().kinetic_energy);
  EXPECT_LT(world.assembly_measures().kinetic_energy, 1e-6 * weight * 0.0976);
}

// The plate placed on a sample of superquadrics stands off their surface,
// not their bounding circles: Table 1's rectangle (n = 4, a = 0.195,
// b = 0.0976) lying flat reaches b up; its bounding circle reaches past a.
TEST(SuperquadricWorld, FurthestReachIsTheSurfaceNotTheBoundingCircle) {
  WorldDef def = nine(true);
  def.particles.resize(1);
  def.particles[0].position = {150.0, 150.0};
  def.particles[0].shape = ShapeDefT<2>{0.195, 0.0976, 4.0, 0.0};
  const World world(def);
  EXPECT_NEAR(world.furthest_reach(Vec2::UnitY()), 150.0976, 1e-9);
  EXPECT_NEAR(world.furthest_reach(Vec2::UnitX()), 150.195, 1e-9);
  const double diagonal = world.furthest_reach(Vec2(1.0, 1.0).normalized());
  EXPECT_LT(diagonal - 150.0 * std::sqrt(2.0),
            world.particles().radius[ParticleId{0}]);  // the corner, inside the circle
}

// Two of Miyata's Table 1 rectangles lying flat, one on the other, pressed
// by a plate: the plate's force rises with its travel and never falls. With
// the force at P_i and P_j, which run along a flat side as the cube root
// of a tilt, the pair rocked and the force fell back by 2-4 % again and
// again (superquadric.h).
TEST(SuperquadricWorld, AFlatStackPressedByAPlateNeverGivesWay) {
  WorldDef def;
  def.materials = {MaterialDef{"rock", 1650.0, 0.51, 0.0}, MaterialDef{"plate", 1.0, 0.51, 0.0}};
  ContactModelDef pairs = testing::linear_model(1e7, 1e7, MaterialId{0}, MaterialId{0});
  ContactModelDef walls = testing::linear_model(1e8, 1e8, MaterialId{0}, MaterialId{1});
  for (ContactModelDef* m : {&pairs, &walls}) {
    m->law = ContactLaw::kLinearRestitution;
    m->restitution = 0.01;
  }
  def.contact_models = {pairs, walls};
  const double b = 0.0976;
  ParticleDef lower, upper;
  lower.shape = upper.shape = ShapeDefT<2>{0.195, b, 4.0, 0.0};
  lower.position = {0.0, b - 0.001};
  upper.position = {0.0, 3.0 * b - 0.002};
  def.particles = {lower, upper};
  def.walls = {WallDef{"bottom", {-2, 0}, {1, 0}, 0, 4, MaterialId{1}, {}},
               WallDef{"top", {2, 4.0 * b + 0.003}, {-1, 0}, 0, 4, MaterialId{1}, {}}};
  def.walls[1].motion.velocity = {0.0, -0.01};
  def.fixed_time_step = 1.7078e-4;  // Miyata Table 2
  World world(def);
  double previous = 0.0, largest_fall = 0.0;
  for (int step = 0; step < 400; ++step) {
    world.cycle(100);
    const double force = world.wall_measures()[1].normal_force;
    if (previous > 1e4) largest_fall = std::max(largest_fall, (previous - force) / previous);
    previous = force;
  }
  std::printf("plate force %.4g N after %.3f m; largest fall between samples %.2e of the force\n", previous,
              world.wall_settlement(WallId{1}), largest_fall);
  EXPECT_GT(previous, 4e5);
  EXPECT_LT(largest_fall, 1e-3);
}

}  // namespace
}  // namespace dem
