// The same engine in three dimensions: spheres, rectangular walls,
// vector spins and quaternion orientations.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact_batch.h"
#include "dem/packing.h"
#include "dem/world.h"
#include "exact_continuation.h"
#include "model_builders.h"
#include "same_bits.h"
#include "set_choices.h"

namespace dem {
namespace {

WallDef3 floor_wall(double half) {
  WallDef3 floor;
  floor.name = "floor";
  floor.point = Vec3::Zero();
  floor.direction = Vec3::UnitX();
  floor.direction2 = Vec3::UnitY();  // normal u x v = +z
  floor.h1 = floor.k1 = -half;
  floor.h2 = floor.k2 = half;
  floor.material = MaterialId{1};
  return floor;
}

WorldDef3 spheres_in_a_box(int per_side, int threads, int layers = 0) {
  WorldDef3 def;
  def.materials = {MaterialDef{"sphere", 2500.0, 0.5, 0.0}, MaterialDef{"wall", 1.0, 0.3, 0.0}};
  def.contact_models = {testing::linear_model(1.0e5, 0.8e5)};
  // A simple cubic stack of touching spheres that gravity presses together.
  LatticeDef3 lattice;
  lattice.radius = 0.0038;
  lattice.spacing = 0.0076;
  lattice.origin = {0.0041, 0.0041, 0.0039};
  lattice.columns = lattice.rows = per_side;
  lattice.layers = layers > 0 ? layers : per_side;
  def.particles = generate_lattice(lattice);
  // Every other sphere slightly smaller, so the stack is not perfectly regular.
  for (std::size_t i = 0; i < def.particles.size(); i += 2) def.particles[i].radius *= 0.98;
  // A box: floor and four side walls, all facing inwards.
  WallDef3 floor = floor_wall(0.05);
  floor.point = {0.05, 0.05, 0.0};
  auto side = [&](const char* name, Vec3 point, Vec3 u, Vec3 v) {
    WallDef3 w = floor;
    w.name = name;
    w.point = point;
    w.direction = u;
    w.direction2 = v;
    w.h1 = -0.05;
    w.h2 = 0.05;
    w.k1 = 0.0;
    w.k2 = 0.4;
    return w;
  };
  def.walls = {floor, side("x0", {0.0, 0.05, 0.0}, Vec3::UnitY(), Vec3::UnitZ()),  // normal +x
               side("x1", {0.1, 0.05, 0.0}, Vec3::UnitZ(), Vec3::UnitY()),         // normal -x
               side("y0", {0.05, 0.0, 0.0}, Vec3::UnitZ(), Vec3::UnitX()),         // normal +y
               side("y1", {0.05, 0.1, 0.0}, Vec3::UnitX(), Vec3::UnitZ())};        // normal -y
  def.walls[2].h1 = def.walls[3].h1 = 0.0;
  def.walls[2].h2 = def.walls[3].h2 = 0.4;
  def.walls[2].k1 = def.walls[3].k1 = -0.05;
  def.walls[2].k2 = def.walls[3].k2 = 0.05;
  def.gravity = {0.0, 0.0, -9.81};
  def.damping = {1e-4, 2.0};
  def.time_step_fraction = 0.2;
  def.threads = threads;
  return def;
}

TEST(World3, SphereRestsOnARectangularFloorUnderItsWeight) {
  WorldDef3 def;
  def.materials = {MaterialDef{"sphere", 2500.0, 0.5, 0.0}, MaterialDef{"wall", 1.0, 0.5, 0.0}};
  def.contact_models = {testing::linear_model(1.0e5, 1.0e5)};
  def.particles = {ParticleDef3{{0.2, -0.1, 0.011}, 0.01, MaterialId{0}}};
  def.walls = {floor_wall(0.5)};
  def.gravity = {0.0, 0.0, -9.81};
  def.damping = {1e-3, 5.0};
  World3 world(def);
  world.cycle(20000);
  const double mass = 2500.0 * 4.0 / 3.0 * std::numbers::pi * 1e-6;
  const WallMeasure3 floor = world.wall_measures()[0];
  EXPECT_EQ(floor.contacts, 1);
  EXPECT_NEAR(floor.normal_force, mass * 9.81, 1e-9 * mass * 9.81);
  EXPECT_NEAR(floor.force.z(), -mass * 9.81, 1e-9 * mass * 9.81);
  // Eccentricity per direction of the rectangle: (0.2, -0.1) over half sizes 0.5.
  EXPECT_NEAR(floor.eccentricity.x(), 0.4, 1e-9);
  EXPECT_NEAR(floor.eccentricity.y(), -0.2, 1e-9);
  EXPECT_NEAR(world.particles().position[ParticleId{0}].z(), 0.01 - mass * 9.81 / 1.0e5, 1e-9);
  EXPECT_DOUBLE_EQ(world.wall_area(WallId{0}), 1.0);
}

TEST(World3, ObliqueFrictionalCollisionConservesMomentum) {
  WorldDef3 def;
  def.materials = {MaterialDef{"sphere", 2500.0, 0.3, 0.0}};
  def.contact_models = {testing::linear_model(1.0e5, 0.8e5)};
  def.particles = {ParticleDef3{{0.0, 0.0, 0.0}, 0.01, MaterialId{0}, {1.0, 0.2, -0.1}, {0.0, 5.0, 0.0}},
                   ParticleDef3{{0.025, 0.006, 0.004}, 0.012, MaterialId{0}, {-0.5, 0.0, 0.3}, {1.0, 0.0, -2.0}}};
  def.damping = {1e-4, 0.0};
  def.time_step_fraction = 0.05;
  World3 world(def);
  auto linear_momentum = [&] {
    const auto p = world.particles();
    return Vec3(p.mass[ParticleId{0}] * p.velocity[ParticleId{0}] + p.mass[ParticleId{1}] * p.velocity[ParticleId{1}]);
  };
  // Angular momentum about the origin in the form central differences
  // carry: r_N x m v_(N+1/2) + I omega_(N+1/2), with r_N = r_(N+1) - v dt.
  auto angular_momentum = [&] {
    const auto p = world.particles();
    Vec3 l = Vec3::Zero();
    for (int i = 0; i < 2; ++i) {
      const double inertia = 0.4 * p.mass[ParticleId::from_index(i)] * p.radius[ParticleId::from_index(i)] *
                             p.radius[ParticleId::from_index(i)];
      const Vec3 r = p.position[ParticleId::from_index(i)] - world.time_step() * p.velocity[ParticleId::from_index(i)];
      l += r.cross(p.mass[ParticleId::from_index(i)] * p.velocity[ParticleId::from_index(i)]) +
           inertia * p.angular_velocity[ParticleId::from_index(i)];
    }
    return l;
  };
  const Vec3 p0 = linear_momentum(), l0 = angular_momentum();
  int touching = 0;
  for (int k = 0; k < 4000; ++k) {
    world.cycle();
    touching += !world.contacts().empty();
  }
  ASSERT_GT(touching, 10) << "the spheres must collide";
  EXPECT_LT((linear_momentum() - p0).norm(), 1e-12 * p0.norm());
  // BALL takes the tangential force's arm as the radius R, not the distance
  // to the contact point, so each cycle the pair's torque misses
  // overlap x e x T: angular momentum holds to about overlap / R.
  const double drift = (angular_momentum() - l0).norm() / l0.norm();
  std::printf("angular momentum drift %.3g over the collision\n", drift);
  EXPECT_LT(drift, 1e-2);
  // Friction made the spheres spin differently and the orientations moved.
  EXPECT_GT(world.particles().rotation[ParticleId{0}].angularDistance(Quaternion::Identity()), 1e-3);
}

TEST(World3, SameStateHashForOneAndTwoThreadsAndAfterRestore) {
  World3 serial(spheres_in_a_box(13, 1)), parallel(spheres_in_a_box(13, 2));  // 2196 spheres
  serial.cycle(600);
  parallel.cycle(600);
  std::printf("3D: %d spheres, %zu contacts, hash %016llx / %016llx\n", serial.particle_count(),
              serial.contacts().size(), static_cast<unsigned long long>(serial.state_hash()),
              static_cast<unsigned long long>(parallel.state_hash()));
  EXPECT_GT(serial.contacts().size(), 1000u);
  EXPECT_EQ(serial.state_hash(), parallel.state_hash());
  World3 restored(serial.snapshot());
  EXPECT_EQ(restored.state_hash(), serial.state_hash());
  serial.cycle(300);
  restored.cycle(300);
  EXPECT_EQ(restored.state_hash(), serial.state_hash());
}

// The common case runs as plain vector loops (motion_plain.h, the batched
// pair pass); with the energy budget on, the same step runs through the
// general row-by-row code. Both compute Cundall & Strack's cycle in the same
// order of operations, so they must agree to the bit.
TEST(World3, PlainLoopsGiveTheSameBitsAsTheGeneralStep) {
  WorldDef3 plain_def = spheres_in_a_box(9, 1), budget_def = plain_def;  // 729 spheres
  budget_def.energy_budget = true;
  World3 plain(plain_def), budget(budget_def);
  plain.cycle(800);
  budget.cycle(800);
  const auto& a = plain.particles();
  const auto& b = budget.particles();
  ASSERT_EQ(plain.particle_count(), budget.particle_count());
  double turned = 0.0;
  for (const ParticleId i : plain.particle_ids()) {
    ASSERT_EQ(a.position[i], b.position[i]) << "particle " << i;
    ASSERT_EQ(a.velocity[i], b.velocity[i]) << "particle " << i;
    ASSERT_EQ(a.angular_velocity[i], b.angular_velocity[i]) << "particle " << i;
    ASSERT_EQ(a.rotation[i].coeffs(), b.rotation[i].coeffs()) << "particle " << i;
    turned = std::max(turned, a.rotation[i].angularDistance(Quaternion::Identity()));
  }
  std::printf("%d spheres, %zu contacts, largest turn %.3g rad: same bits\n", plain.particle_count(),
              plain.contacts().size(), turned);
  EXPECT_GT(turned, 1e-6) << "the spheres must turn for the orientations to be compared";
}

// The wall rows of round particles run through a batched pass
// (wall_batch.h) when the energy budget is off, and through the general row
// body (contact_row.h) when it is on: the same bits, the walls' sums with
// them. The particles lie apart from each other, so the pair rows add
// nothing; they bounce on a turning floor (its velocity at the contact
// point enters the rows; contacts form and end) under a lid held by a servo,
// which moves by the normal force it measures.
TEST(World3, BatchedWallRowsGiveTheSameBitsAsTheGeneralRows) {
  WorldDef3 plain_def = spheres_in_a_box(6, 1, 1);  // one layer
  plain_def.materials.resize(1);
  for (WallDef3& wall : plain_def.walls) wall.material = MaterialId{0};
  for (ParticleDef3& sphere : plain_def.particles) sphere.radius *= 0.8;
  plain_def.walls[0].motion.angular_velocity = {0.0, 0.0, 0.5};
  WallDef3 lid = plain_def.walls[0];
  lid.name = "lid";
  lid.point = {0.05, 0.05, 0.0072};
  lid.direction = Vec3::UnitY();
  lid.direction2 = Vec3::UnitX();  // normal -z
  lid.motion = {};
  lid.motion.servo = ServoDef{0.05, 1.0, 0.05};
  plain_def.walls.push_back(lid);
  testing::expect_batched_wall_rows_match_the_general_rows<World3>(plain_def, 2000);
}

// Past kPrefetchParticles (contact_blocks.h) the batched pass fetches ahead
// and the law of motion streams the side-by-side copies that the pass reads:
// one and two threads must still give the same state.
TEST(World3, LargeBedsGiveTheSameStateHashForOneAndTwoThreads) {
  WorldDef3 serial_def = spheres_in_a_box(9, 1, 405);  // a column
  // Spheres a little larger than the lattice's spacing: every neighbour
  // touches from the first cycle.
  for (ParticleDef3& sphere : serial_def.particles) sphere.radius *= 1.015;
  // Spheres of three materials whose parameter sets differ (each row
  // finds its own, parameter_sets.h), and no walls.
  testing::spread_materials(serial_def, 3, 1.0e9);
  serial_def.walls.clear();
  ASSERT_GT(static_cast<std::int64_t>(serial_def.particles.size()), kPrefetchParticles);
  WorldDef3 parallel_def = serial_def;
  parallel_def.threads = 2;
  World3 serial(serial_def), parallel(parallel_def);
  serial.cycle(60);
  parallel.cycle(60);
  std::printf("%d spheres, %zu contacts, hash %016llx / %016llx\n", serial.particle_count(), serial.contacts().size(),
              static_cast<unsigned long long>(serial.state_hash()),
              static_cast<unsigned long long>(parallel.state_hash()));
  EXPECT_GT(serial.contacts().size(), 30000u) << "the copies must be read by touching rows";
  EXPECT_EQ(serial.state_hash(), parallel.state_hash());
}

// A bed of one material, and the same bed with its walls and every other
// sphere given copies of that material: the same parameter sets, so the
// same bits and the same hash (the hash reads no material ids). Then copies
// that differ only in Young's modulus, which the linear law does not read:
// the rows' sets differ, so the batched passes choose each row's set among
// a few (two particle materials) or look it up among many (three; six sets
// of sphere pairs), and must still give the one material's bits.
TEST(World3, EqualMaterialsGiveTheSameBitsAsOne) {
  WorldDef3 one_def = spheres_in_a_box(9, 1);  // 729 spheres
  one_def.materials.resize(1);
  for (WallDef3& wall : one_def.walls) wall.material = MaterialId{0};
  World3 one(one_def);
  one.cycle(600);
  ASSERT_GT(one.contacts().size(), 500u);
  struct Variant {
    int particle_materials;
    double modulus_step;
    SetChoice pairs, walls;
  };
  for (const Variant& v :
       {Variant{2, 0.0, SetChoice::kOne, SetChoice::kOne}, Variant{2, 1.0e9, SetChoice::kFew, SetChoice::kFew},
        Variant{3, 1.0e9, SetChoice::kMany, SetChoice::kFew}}) {
    WorldDef3 def = one_def;
    testing::spread_materials(def, v.particle_materials, v.modulus_step);
    const testing::SetChoices choices = testing::set_choices(def);
    EXPECT_EQ(choices.pairs, v.pairs);
    EXPECT_EQ(choices.walls, v.walls);
    World3 spread(def);
    spread.cycle(600);
    std::printf("%d sphere materials, modulus step %g Pa: hash %016llx, one material %016llx\n", v.particle_materials,
                v.modulus_step, static_cast<unsigned long long>(spread.state_hash()),
                static_cast<unsigned long long>(one.state_hash()));
    ASSERT_NO_FATAL_FAILURE(testing::expect_same_particles_and_walls(one, spread));
    EXPECT_EQ(spread.state_hash(), one.state_hash());
  }
}

// Spheres of three materials whose friction and stiffnesses differ by pair
// (six sets of sphere pairs, three of sphere and wall): the batched passes
// (energy budget off) and the row-by-row passes (on) add the same shares
// in the same order, so they agree to the bit; one and two threads and a
// restart from a snapshot agree with the uninterrupted run.
WorldDef3 three_materials(int threads) {
  WorldDef3 def = spheres_in_a_box(9, threads);
  def.materials = {MaterialDef{"a", 2500.0, 0.5, 0.0}, MaterialDef{"wall", 1.0, 0.45, 0.0},
                   MaterialDef{"b", 2500.0, 0.4, 0.0}, MaterialDef{"c", 2500.0, 0.6, 0.0}};
  testing::three_kinds_with_pair_models(def, {MaterialId{0}, MaterialId{2}, MaterialId{3}}, 1.0e5, 0.8e5);
  return def;
}

TEST(World3, DistinctMaterialsGiveTheRowByRowBits) {
  WorldDef3 plain_def = three_materials(1), budget_def = plain_def;
  budget_def.energy_budget = true;
  const testing::SetChoices choices = testing::set_choices(plain_def);
  EXPECT_EQ(choices.pairs, SetChoice::kMany);
  EXPECT_EQ(choices.walls, SetChoice::kFew);
  World3 plain(plain_def), budget(budget_def);
  plain.cycle(600);
  budget.cycle(600);
  EXPECT_GT(plain.contacts().size(), 200u);
  ASSERT_NO_FATAL_FAILURE(testing::expect_same_particles_and_walls(plain, budget));
  EXPECT_EQ(plain.state_hash(), budget.state_hash());
}

TEST(World3, DistinctMaterialsRestartExactlyAndThreadsAgree) {
  testing::expect_exact_continuation(three_materials(1), 300, 600, "three sphere materials");
}

TEST(World3, RectangleWallsAreValidated) {
  WorldDef3 def = spheres_in_a_box(4, 1);
  def.walls[0].direction2 = Vec3(1.0, 1.0, 0.0).normalized();  // not perpendicular to u
  EXPECT_THROW(World3{def}, std::invalid_argument);
  def = spheres_in_a_box(4, 1);
  def.walls[0].k2 = def.walls[0].k1;
  EXPECT_THROW(World3{def}, std::invalid_argument);
}

}  // namespace
}  // namespace dem
