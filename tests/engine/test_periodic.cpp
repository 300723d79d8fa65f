// Periodic boundaries: particles interact through the nearest image and
// wrap into the cell; plates across the cell take their stress over it.
#include <gtest/gtest.h>

#include <cmath>

#include "broad_phase.h"
#include "dem/error.h"
#include "dem/packing.h"
#include "dem/world.h"
#include "model_builders.h"

namespace dem {
namespace {

TEST(Periodic, DiscsCollideThroughTheBoundary) {
  WorldDef def;
  def.materials = {MaterialDef{"disc", 1000.0, 0.0, 0.0}};
  def.contact_models = {testing::linear_model(1e6, 1e6)};
  // Each disc heads out of the cell; through the boundary they meet head on.
  def.particles = {ParticleDef{{0.012, 0.5}, 0.01, MaterialId{0}, {-1.0, 0.0}, 0.0},
                   ParticleDef{{0.988, 0.5}, 0.01, MaterialId{0}, {1.0, 0.0}, 0.0}};
  def.periodic.axes = {true, false};
  def.periodic.min = {0.0, 0.0};
  def.periodic.max = {1.0, 0.0};
  def.time_step_fraction = 0.02;
  World world(def);
  int touching = 0;
  for (int k = 0; k < 20000 && !(touching > 0 && world.contacts().empty()); ++k) {
    world.cycle();
    touching += !world.contacts().empty();
  }
  const auto p = world.particles();
  std::printf("velocities after the collision: %.6f %.6f, %d cycles in contact\n", p.velocity[ParticleId{0}].x(),
              p.velocity[ParticleId{1}].x(), touching);
  EXPECT_GT(touching, 10);
  // Equal discs, elastic and frictionless: they exchange velocities.
  EXPECT_NEAR(p.velocity[ParticleId{0}].x(), 1.0, 1e-3);
  EXPECT_NEAR(p.velocity[ParticleId{1}].x(), -1.0, 1e-3);
  for (const Vec2& x : p.position) {
    EXPECT_GE(x.x(), 0.0);
    EXPECT_LT(x.x(), 1.0);
  }
}

// Pairs found by the cell grid equal those of a brute-force nearest-image search.
void expect_brute_force_pairs(int per_side, double period) {
  Particles<2> p;
  LatticeDef lattice;
  lattice.radius = 0.01;
  lattice.spacing = period / per_side;
  lattice.columns = lattice.rows = per_side;
  lattice.origin = {0.001, 0.002};
  for (const ParticleDef& d : generate_lattice(lattice)) {
    p.id.push_back(ParticleId::from_index(p.position.size()));
    p.position.push_back(d.position);
    p.radius.push_back(d.radius * (1.0 + 0.3 * std::sin(37.0 * d.position.x())));
  }
  PeriodicDef def;
  def.axes = {true, true};
  def.max = {period, period};
  const Periodic<2> periodic = Periodic<2>::from(def);
  const double tolerance = 0.004;
  const auto found = find_pair_keys(p, periodic, tolerance, 1);
  std::vector<ContactKey> expected;
  for (int i = 0; i < static_cast<int>(p.size()); ++i) {
    for (int j = i + 1; j < static_cast<int>(p.size()); ++j) {
      if (periodic.separation(p.position[i], p.position[j]).norm() - p.radius[i] - p.radius[j] < tolerance) {
        expected.push_back({i, j});
      }
    }
  }
  ASSERT_EQ(found.size(), expected.size()) << per_side << " per side, period " << period;
  for (std::size_t k = 0; k < found.size(); ++k) {
    EXPECT_EQ(found[k].first, expected[k].first);
    EXPECT_EQ(found[k].second, expected[k].second);
  }
}

TEST(Periodic, CellGridFindsTheNearestImagePairs) {
  expect_brute_force_pairs(12, 0.26);  // many cells per period
  expect_brute_force_pairs(4, 0.11);   // two cells per period: neighbours coincide
}

TEST(Periodic, TooSmallAPeriodIsRefused) {
  WorldDef def;
  def.materials = {MaterialDef{"disc", 1000.0, 0.0, 0.0}};
  def.contact_models = {testing::linear_model(1e6, 1e6)};
  def.particles = {ParticleDef{{0.01, 0.0}, 0.01, MaterialId{0}}};
  def.periodic.axes = {true, false};
  def.periodic.max = {0.03, 0.0};  // under twice (2 R + TOL) = 0.042
  EXPECT_THROW(World{def}, DefinitionError);
}

// Two bodies thrown at each other, once through the periodic boundary and
// once in the middle of the cell: the same collision, to round-off and
// the contact search's tolerance.
template <int Dim>
void expect_same_collision(WorldDefT<Dim> through, const Vec<Dim>& shift, int cycles, const char* what) {
  WorldDefT<Dim> inside = through;
  for (ParticleDefT<Dim>& p : inside.particles) {
    p.position += shift;
    for (int d = 0; d < Dim; ++d) {
      if (!through.periodic.axes[d]) continue;
      const double period = through.periodic.max[d] - through.periodic.min[d];
      p.position[d] -= period * std::floor((p.position[d] - through.periodic.min[d]) / period);
    }
  }
  BasicWorld<Dim> a(through), b(inside);
  int touching = 0;
  for (int k = 0; k < cycles; ++k) {
    a.cycle();
    b.cycle();
    touching += !a.contacts().empty();
  }
  const auto pa = a.particles(), pb = b.particles();
  double gap = 0.0;
  for (int i = 0; i < 2; ++i) {
    double spin_gap = 0.0;
    if constexpr (Dim == 2) {
      spin_gap =
          std::abs(pa.angular_velocity[ParticleId::from_index(i)] - pb.angular_velocity[ParticleId::from_index(i)]);
    } else {
      spin_gap =
          (pa.angular_velocity[ParticleId::from_index(i)] - pb.angular_velocity[ParticleId::from_index(i)]).norm();
    }
    gap = std::max(
        {gap, (pa.velocity[ParticleId::from_index(i)] - pb.velocity[ParticleId::from_index(i)]).norm(), spin_gap});
  }
  std::printf("%s: %d cycles in contact, velocities after (%.6f, %.6f), largest difference %.2e\n", what, touching,
              pa.velocity[ParticleId{0}].x(), pa.velocity[ParticleId{1}].x(), gap);
  EXPECT_GT(touching, 10);
  EXPECT_TRUE(a.contacts().empty());  // the collision is over
  // They did collide: the first body's velocity changed by a good part of itself.
  EXPECT_GT((pa.velocity[ParticleId{0}] - through.particles[0].velocity).norm(),
            0.5 * through.particles[0].velocity.norm());
  // m/s and rad/s: the positions differ in their last bits, and the
  // iterative contact searches of shaped particles converge to their own
  // tolerance from there.
  EXPECT_LT(gap, 1e-6);
}

TEST(Periodic, SuperquadricsCollideThroughTheBoundaryAsInside) {
  WorldDef def;
  def.materials = {MaterialDef{"rock", 1650.0, 0.5, 0.0}};
  def.contact_models = {testing::linear_model(1e7, 1e7)};
  const ShapeDefT<2> rock{0.195, 0.0976, 4.0, 0.4};  // Miyata's Table 1 particle
  def.particles = {
      ParticleDef{{0.25, 1.0}, 0.195, MaterialId{0}, {-1.0, 0.05}, 0.0, rock},
      ParticleDef{{4.78, 1.1}, 0.195, MaterialId{0}, {1.0, 0.0}, 0.0, ShapeDefT<2>{0.195, 0.0976, 4.0, -0.3}}};
  def.periodic.axes = {true, false};
  def.periodic.max = {5.0, 0.0};
  def.fixed_time_step = 1.7078e-4;  // Table 2
  expect_same_collision<2>(def, {2.5, 0.0}, 3000, "superquadrics through x");
}

TEST(Periodic, EllipsoidsCollideThroughACornerAsInside) {
  WorldDef3 def;
  def.materials = {MaterialDef{"rock", 2650.0, 0.6, 0.0, 70e9, 0.2}};
  ContactModelDef model;
  model.law = ContactLaw::kHertzLinearTangential;
  model.hertz.restitution = 0.5;
  def.contact_models = {model};
  ParticleDef3 a, b;
  a.position = {0.3, 0.25, 1.0};
  a.velocity = {-0.5, -0.5, 0.0};
  a.shape = {{0.371, 0.260, 0.182}, Quaternion(Eigen::AngleAxisd(0.6, Vec3(1.0, 2.0, 0.5).normalized()))};
  b.position = {9.75, 9.72, 1.05};
  b.velocity = {0.5, 0.5, 0.0};
  b.shape = {{0.371, 0.260, 0.182}, Quaternion(Eigen::AngleAxisd(-1.1, Vec3(0.2, 1.0, 1.0).normalized()))};
  def.particles = {a, b};
  def.periodic.axes = {true, true, false};
  def.periodic.max = {10.0, 10.0, 0.0};  // section 3.3's 10 m x 10 m box
  def.fixed_time_step = 6.86e-6;
  expect_same_collision<3>(def, {5.0, 5.0, 0.0}, 40000, "ellipsoids through the x-y corner");
}

WorldDef3 periodic_bed(int threads) {
  WorldDef3 def;
  def.materials = {MaterialDef{"glass", 2500.0, 0.5, 0.0, 1e7, 0.3}};
  ContactModelDef model;
  model.law = ContactLaw::kHertzLinearTangential;
  model.hertz.restitution = 0.5;
  model.hertz.tangential = true;
  def.contact_models = {model};
  RandomPackingDef3 packing;
  packing.max = {0.02, 0.02, 0.06};
  packing.sizes = {{0.001, 1500}};
  packing.seed = 9;
  def.particles = generate_random_packing(packing);
  WallDef3 floor;
  floor.name = "floor";
  floor.h1 = floor.k1 = -1.0;  // far past the cell: a plane across the periodic footprint
  floor.h2 = floor.k2 = 1.0;
  def.walls = {floor};
  def.periodic.axes = {true, true, false};
  def.periodic.max = {0.02, 0.02, 0.0};
  def.gravity = {0.0, 0.0, -9.81};
  def.time_step_fraction = 0.2;
  def.threads = threads;
  return def;
}

TEST(Periodic, BedSettlesDeterministicallyAndPlateStressUsesTheCell) {
  World3 serial(periodic_bed(1)), parallel(periodic_bed(2));
  serial.cycle(3000);
  parallel.cycle(3000);
  EXPECT_EQ(serial.state_hash(), parallel.state_hash());
  World3 restored(serial.snapshot());
  serial.cycle(200);
  restored.cycle(200);
  EXPECT_EQ(serial.state_hash(), restored.state_hash());
  // The floor spans 2 m x 2 m but the periodic cell is 20 mm x 20 mm.
  EXPECT_NEAR(serial.wall_area(WallId{0}), 0.02 * 0.02, 1e-15);
  int across = 0;
  const auto p = serial.particles();
  for (const ContactRecord3& c : serial.contacts()) {
    if (c.second_particle == kInvalidId) continue;
    across += (p.position[c.first] - p.position[c.second_particle]).norm() > 0.01;
  }
  std::printf("%zu contacts, %d of them across the periodic boundary\n", serial.contacts().size(), across);
  EXPECT_GT(across, 10);
}

}  // namespace
}  // namespace dem
