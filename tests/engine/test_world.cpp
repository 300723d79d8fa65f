// The World API: construction errors, wall steering, measures, determinism.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/error.h"
#include "dem/packing.h"
#include "dem/world.h"
#include "model_builders.h"
#include "same_bits.h"
#include "set_choices.h"

namespace dem {
namespace {

// A dense box of discs under gravity: enough particles for the parallel
// loops to run threaded (they stay serial below 2048 items).
WorldDef dense_box(int columns, int rows) {
  WorldDef def;
  def.materials = {MaterialDef{"disc", 2650.0, 0.5, 0.0}, MaterialDef{"wall", 1.0, 0.3, 0.0}};
  def.contact_models = {testing::linear_model(1.0e6, 0.7e6)};
  LatticeDef lattice;
  lattice.radius = 0.01;
  lattice.origin = {0.011, 0.011};
  lattice.columns = columns;
  lattice.rows = rows;
  lattice.spacing = 0.0205;
  lattice.arrangement = LatticeArrangement::kHexagonal;
  def.particles = generate_lattice(lattice);
  // Slightly varied radii, so the packing is not perfectly regular.
  for (std::size_t i = 0; i < def.particles.size(); ++i) def.particles[i].radius *= 1.0 - 0.05 * double(i % 7) / 7.0;
  const double width = columns * 0.0205 + 0.012, height = rows * 0.0205 + 0.012;
  def.walls = {WallDef{"bottom", {0, 0}, {1, 0}, 0, width, MaterialId{1}, {}},
               WallDef{"right", {width, 0}, {0, 1}, 0, 2 * height, MaterialId{1}, {}},
               WallDef{"left", {0, 2 * height}, {0, -1}, 0, 2 * height, MaterialId{1}, {}}};
  def.gravity = {0.0, -9.81};
  def.damping = {1e-5, 1.0};
  def.time_step_fraction = 0.2;
  return def;
}

TEST(World, SameStateHashForOneAndTwoThreads) {
  WorldDef def = dense_box(80, 40);  // 3200 discs
  def.threads = 1;
  World serial(def);
  def.threads = 2;
  World parallel(def);
  EXPECT_EQ(serial.state_hash(), parallel.state_hash());
  serial.cycle(300);
  parallel.cycle(300);
  std::printf("hash after 300 cycles: 1 thread %016llx, 2 threads %016llx, %zu contacts\n",
              static_cast<unsigned long long>(serial.state_hash()),
              static_cast<unsigned long long>(parallel.state_hash()), serial.contacts().size());
  EXPECT_GT(serial.contacts().size(), 3000u);
  EXPECT_EQ(serial.state_hash(), parallel.state_hash());
}

// Discs of three materials whose friction and stiffnesses differ by pair
// (the batched passes look each row's set up among six): one and two
// threads agree, and so do the batched passes (energy budget off) and the
// row-by-row passes (on), which add the same shares in the same order.
TEST(World, DistinctMaterialsGiveOneHashForOneAndTwoThreadsAndTheRowByRowBits) {
  WorldDef def = dense_box(80, 40);  // 3200 discs
  def.materials.push_back(MaterialDef{"disc_b", 2650.0, 0.4, 0.0});
  def.materials.push_back(MaterialDef{"disc_c", 2650.0, 0.6, 0.0});
  testing::three_kinds_with_pair_models(def, {MaterialId{0}, MaterialId{2}, MaterialId{3}}, 1.0e6, 0.7e6);
  EXPECT_EQ(testing::set_choices(def).pairs, SetChoice::kMany);
  def.threads = 1;
  World serial(def);
  def.threads = 2;
  World parallel(def);
  def.threads = 1;
  def.energy_budget = true;
  World budget(def);
  serial.cycle(300);
  parallel.cycle(300);
  budget.cycle(300);
  std::printf("three disc materials, 300 cycles: 1 thread %016llx, 2 threads %016llx, row by row %016llx\n",
              static_cast<unsigned long long>(serial.state_hash()),
              static_cast<unsigned long long>(parallel.state_hash()),
              static_cast<unsigned long long>(budget.state_hash()));
  EXPECT_GT(serial.contacts().size(), 2000u);
  EXPECT_EQ(serial.state_hash(), parallel.state_hash());
  ASSERT_NO_FATAL_FAILURE(testing::expect_same_particles_and_walls(serial, budget));
}

// A box of one material, and the same box with copies of it (walls, every
// other disc), then with copies whose parameter sets differ only in what
// the linear law does not read: the same bits (World3's test says more).
TEST(World, EqualMaterialsGiveTheSameBitsAsOne) {
  WorldDef one_def = dense_box(30, 15);
  one_def.materials.resize(1);
  for (WallDef& wall : one_def.walls) wall.material = MaterialId{0};
  World one(one_def);
  one.cycle(400);
  for (const auto& [materials, step] : {std::pair{2, 0.0}, std::pair{2, 1.0e9}, std::pair{3, 1.0e9}}) {
    WorldDef def = one_def;
    testing::spread_materials(def, materials, step);
    World spread(def);
    spread.cycle(400);
    ASSERT_NO_FATAL_FAILURE(testing::expect_same_particles_and_walls(one, spread));
    EXPECT_EQ(spread.state_hash(), one.state_hash());
  }
}

TEST(World, SameCaseGivesSameHash) {
  World a(dense_box(20, 10)), b(dense_box(20, 10));
  a.cycle(200);
  b.cycle(100);
  b.cycle(100);
  EXPECT_EQ(a.state_hash(), b.state_hash());
  World c(dense_box(20, 10));
  c.cycle(199);
  EXPECT_NE(a.state_hash(), c.state_hash());
}

TEST(World, RejectsBadDefinitionsNamingTheItem) {
  auto expect_error = [](WorldDef def, const std::string& fragment) {
    try {
      World world(def);
      ADD_FAILURE() << "accepted a definition that should fail with: " << fragment;
    } catch (const DefinitionError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  WorldDef def = dense_box(3, 3);
  def.particles[4].radius = -1.0;
  expect_error(def, "particle 4: radius");
  def = dense_box(3, 3);
  def.walls[1].h2 = def.walls[1].h1;
  expect_error(def, "wall 1 (\"right\"): h2");
  def = dense_box(3, 3);
  def.contact_models[0].material_a = MaterialId{0};
  def.contact_models[0].material_b = MaterialId{0};  // disc-wall pair has no law now
  expect_error(def, "no contact model for materials \"disc\" and \"wall\"");
  def = dense_box(3, 3);
  def.materials[0].density = 0.0;
  expect_error(def, "material 0 (\"disc\"): density");
  def = dense_box(3, 3);
  def.particles.clear();
  expect_error(def, "no particles");
}

TEST(World, TimeStepIsFractionOfCriticalStep) {
  WorldDef def = dense_box(3, 3);
  World world(def);
  // 2 sqrt(m/k) over the assembly, rotation (I, k_s R^2) included: the
  // smallest disc (radius 0.01 * (1 - 0.05 * 6/7)) with k_s = 0.7e6,
  // shortened by its shear dashpot (c = beta k_s, eq. 28) to
  // 2/omega (sqrt(1 + zeta^2) - zeta), zeta = beta omega / 2.
  const double r = 0.01 * (1.0 - 0.05 * 6.0 / 7.0);
  const double m = 2650.0 * std::acos(-1.0) * r * r;
  const double omega = std::sqrt(0.7e6 * r * r / (0.5 * m * r * r));
  const double zeta = def.damping.contact_beta * omega / 2.0;
  const double rotational = 2.0 / omega * (std::sqrt(1.0 + zeta * zeta) - zeta);
  EXPECT_NEAR(world.critical_time_step(), rotational, 1e-14 * rotational);
  // A fraction is of the undamped step, 2 sqrt(I / (k_s R^2)).
  EXPECT_DOUBLE_EQ(world.undamped_critical_time_step(), 2.0 / omega);
  EXPECT_DOUBLE_EQ(world.time_step(), 0.2 * 2.0 / omega);
}

TEST(World, WallMeasuresSeeTheWeightOnTheFloor) {
  World world(dense_box(10, 6));
  world.set_damping({1e-4, 20.0});
  world.cycle(20000);
  double weight = 0.0;
  for (double m : world.particles().mass) weight += 9.81 * m;
  const auto walls = world.wall_measures();
  // Side walls are vertical: the floor carries the weight less the side walls' friction.
  const double carried = walls[0].force.y() + walls[1].force.y() + walls[2].force.y();
  std::printf("weight %.6g N, walls carry %.6g N (floor %.6g, %d contacts), out-of-balance %.3g\n", weight, -carried,
              -walls[0].force.y(), walls[0].contacts, world.assembly_measures().out_of_balance);
  EXPECT_NEAR(-carried, weight, 1e-3 * weight);
  EXPECT_EQ(walls[0].contacts, 10);
  EXPECT_GT(walls[0].normal_force, 0.0);
  EXPECT_LT(world.assembly_measures().out_of_balance, 1e-3);
}

// The wall rows of round particles run through a batched pass
// (wall_batch.h) when the energy budget is off, and through the general row
// body (contact_row.h) when it is on: the same bits, the walls' sums with
// them. The particles lie apart from each other, so the pair rows add
// nothing; they bounce on a turning floor (its velocity at the contact
// point enters the rows; contacts form and end) under a lid held by a servo,
// which moves by the normal force it measures.
TEST(World, BatchedWallRowsGiveTheSameBitsAsTheGeneralRows) {
  WorldDef plain_def = dense_box(12, 1);  // one row
  plain_def.materials.resize(1);
  for (WallDef& wall : plain_def.walls) wall.material = MaterialId{0};
  for (ParticleDef& disc : plain_def.particles) disc.radius *= 0.7;
  plain_def.walls[0].motion.angular_velocity = 0.05;
  const double width = 12 * 0.0205 + 0.012;
  WallMotion servo;
  servo.servo = ServoDef{50.0, 2e-3, 0.1};
  plain_def.walls.push_back(WallDef{"lid", {width, 0.02}, {-1, 0}, 0, width, MaterialId{0}, servo});  // normal -y
  testing::expect_batched_wall_rows_match_the_general_rows<World>(plain_def, 600);
}

// One wall's contacts are those of contacts() with that wall, in order
// (dem_server's wall queries read them without a pass over every contact).
TEST(World, WallContactsAreTheWallsOwnOfAllContacts) {
  World world(dense_box(10, 6));
  world.cycle(200);
  const std::vector<ContactRecord> all = world.contacts();
  for (int w = 0; w < world.wall_count(); ++w) {
    const WallId wall{w};
    std::vector<ContactRecord> expected;
    for (const ContactRecord& c : all) {
      if (c.second_wall == wall) expected.push_back(c);
    }
    const std::vector<ContactRecord> found = world.wall_contacts(wall);
    ASSERT_EQ(found.size(), expected.size()) << wall;
    for (std::size_t k = 0; k < found.size(); ++k) {
      EXPECT_EQ(found[k].first, expected[k].first);
      EXPECT_EQ(found[k].normal_force, expected[k].normal_force);
      EXPECT_EQ(found[k].point, expected[k].point);
    }
  }
  EXPECT_FALSE(world.wall_contacts(WallId{0}).empty());  // the floor carries the discs
}

TEST(World, WallMotionMovesWallAndReportsSettlement) {
  World world(dense_box(3, 3));
  const WallId left = world.find_wall("left");
  ASSERT_EQ(left, WallId{2});
  EXPECT_EQ(world.find_wall("nope"), kInvalidId);
  WallMotion motion;
  motion.velocity = {0.01, 0.0};
  world.set_wall_motion(left, motion);
  world.cycle(100);
  const WallMeasure m = world.wall_measures()[left.index()];
  EXPECT_NEAR(m.displacement.x(), 0.01 * 100 * world.time_step(), 1e-15);
  EXPECT_DOUBLE_EQ(m.displacement.y(), 0.0);
}

TEST(World, EccentricityOfASingleOffCentreContact) {
  // One disc resting on a floor wall at a quarter of its length from the
  // centre: e/(L/2) = 0.5 (Cundall & Strack Table 1, note 1).
  WorldDef def;
  def.materials = {MaterialDef{"disc", 1000.0, 0.5, 0.0}};
  def.contact_models = {ContactModelDef{}};
  def.particles = {ParticleDef{{0.5, 0.1 - 1e-5}, 0.1, MaterialId{0}}};
  def.walls = {WallDef{"floor", {0.0, 0.0}, {1.0, 0.0}, -1.0, 1.0, MaterialId{0}, {}}};
  World world(def);
  world.cycle();
  const WallMeasure m = world.wall_measures()[0];
  EXPECT_EQ(m.contacts, 1);
  EXPECT_NEAR(m.eccentricity, 0.5, 1e-12);
  EXPECT_NEAR(m.moment, m.force.y() * 0.5, 1e-9 * std::abs(m.force.y()));
}

}  // namespace
}  // namespace dem
