// The quasi-static measures of AssemblyMeasures (quasi_static.h): the
// deformation rate of a fitted velocity field, the Love-Weber mean stress,
// the inertial number, the unbalanced force and kinetic over elastic energy,
// and the stop conditions built on them.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "dem/packing.h"
#include "dem/programme.h"
#include "dem/world.h"
#include "model_builders.h"
#include "quasi_static.h"

namespace dem {
namespace {

// A block of particles on a lattice moving with v = L x.
Particles<3> moving_block(const Eigen::Matrix3d& gradient) {
  Particles<3> p;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      for (int k = 0; k < 4; ++k) {
        const Vec3 x(0.3 * i, 0.25 * j + 0.01 * i, 0.2 * k);
        p.position.push_back(x);
        p.velocity.push_back(Vec3(0.5, 0.0, -0.2) + gradient * x);
      }
    }
  }
  return p;
}

TEST(QuasiStatic, DeformationRateOfUniaxialCompressionAndSimpleShear) {
  Eigen::Matrix3d uniaxial = Eigen::Matrix3d::Zero();
  uniaxial(2, 2) = -0.05;  // a plate closing at 5 % per second
  EXPECT_NEAR(deformation_rate(moving_block(uniaxial), Periodic<3>{}), 0.05, 1e-12);
  Eigen::Matrix3d shear = Eigen::Matrix3d::Zero();
  shear(0, 2) = 0.3;  // v_x = 0.3 z: a simple shear of rate 0.3
  EXPECT_NEAR(deformation_rate(moving_block(shear), Periodic<3>{}), 0.3, 1e-12);
  // A rigid rotation deforms nothing.
  Eigen::Matrix3d spin = Eigen::Matrix3d::Zero();
  spin(0, 1) = 0.7;
  spin(1, 0) = -0.7;
  EXPECT_NEAR(deformation_rate(moving_block(spin), Periodic<3>{}), 0.0, 1e-12);
}

TEST(QuasiStatic, APeriodicCellDoesNotDeformAlongItsPeriods) {
  // Velocities that vary along a periodic axis are no deformation of the
  // cell: only the gradient along z counts.
  Eigen::Matrix3d gradient = Eigen::Matrix3d::Zero();
  gradient(0, 0) = 0.4;
  gradient(2, 2) = -0.02;
  Periodic<3> periodic;
  periodic.length = Vec3(1.2, 1.0, 0.0);
  EXPECT_NEAR(deformation_rate(moving_block(gradient), periodic), 0.02, 1e-12);
}

TEST(QuasiStatic, InertialNumberFromItsDefinition) {
  // I = rate d sqrt(rho / p) = 2 x 0.1 x sqrt(2500 / 1e4) = 0.1.
  EXPECT_NEAR(inertial_number(2.0, {0.1, 2500.0}, 1e4), 0.1, 1e-15);
  EXPECT_EQ(inertial_number(0.0, {0.1, 2500.0}, 1e4), 0.0);
  EXPECT_EQ(inertial_number(2.0, {0.1, 2500.0}, 0.0), std::numeric_limits<double>::infinity());
}

// One disc of radius r squeezed between two fixed walls an overlap apart.
WorldDef squeezed_disc(double radius, double overlap) {
  WorldDef def;
  def.materials = {MaterialDef{"disc", 2650.0, 0.5, 0.0}};
  def.contact_models = {testing::linear_model(1.0e6, 0.5e6)};
  ParticleDef disc;
  disc.radius = radius;
  def.particles = {disc};
  const double gap = radius - 0.5 * overlap;
  def.walls = {WallDef{"left", {-gap, 1.0}, {0, -1}, 0, 2, MaterialId{0}, {}},
               WallDef{"right", {gap, -1.0}, {0, 1}, 0, 2, MaterialId{0}, {}}};
  return def;
}

TEST(QuasiStatic, MeanStressIsLoveWebersOverTheVolumeTheParticlesSpan) {
  const double r = 0.1, overlap = 1e-3;
  World world(squeezed_disc(r, overlap));
  const auto walls = world.wall_measures();
  ASSERT_EQ(walls[0].contacts, 1);
  const double force = walls[0].normal_force;
  EXPECT_NEAR(force, 1e6 * 0.5 * overlap, 1e-9);
  // sigma_xx = 2 F (r - overlap/4) / V over the disc's bounding square, the
  // contact point halfway through each wall's overlap of 0.5 mm; sigma_yy = 0.
  const double arm = r - 0.25 * overlap;
  const double expected = 0.5 * (2.0 * force * arm / (4.0 * r * r));
  const AssemblyMeasures m = world.assembly_measures();
  std::printf("mean stress %.9g Pa, Love-Weber by hand %.9g Pa\n", m.mean_stress, expected);
  EXPECT_NEAR(m.mean_stress, expected, 1e-9 * expected);
  EXPECT_EQ(m.unbalanced_force, 0.0);  // the two walls balance
  EXPECT_DOUBLE_EQ(m.elastic_energy, 2.0 * 0.5 * force * force / 1e6);
  EXPECT_EQ(m.kinetic_to_elastic, 0.0);
}

// Discs dropped into a box, as test_world's dense box.
WorldDef falling_discs() {
  WorldDef def;
  def.materials = {MaterialDef{"disc", 2650.0, 0.5, 0.0}, MaterialDef{"wall", 1.0, 0.3, 0.0}};
  def.contact_models = {testing::linear_model(1.0e6, 0.7e6)};
  LatticeDef lattice;
  lattice.radius = 0.01;
  lattice.origin = {0.011, 0.011};
  lattice.columns = 10;
  lattice.rows = 6;
  lattice.spacing = 0.0215;
  lattice.arrangement = LatticeArrangement::kHexagonal;
  def.particles = generate_lattice(lattice);
  for (std::size_t i = 0; i < def.particles.size(); ++i) def.particles[i].radius *= 1.0 - 0.05 * double(i % 7) / 7.0;
  const double width = 10 * 0.0215 + 0.012, height = 6 * 0.0215 + 0.012;
  def.walls = {WallDef{"bottom", {0, 0}, {1, 0}, 0, width, MaterialId{1}, {}},
               WallDef{"right", {width, 0}, {0, 1}, 0, 2 * height, MaterialId{1}, {}},
               WallDef{"left", {0, 2 * height}, {0, -1}, 0, 2 * height, MaterialId{1}, {}}};
  def.gravity = {0.0, -9.81};
  def.damping = {1e-4, 20.0};
  def.time_step_fraction = 0.2;
  return def;
}

TEST(QuasiStatic, SettlingStopsOnTheRelativeMeasures) {
  World world(falling_discs());
  world.cycle(200);
  const AssemblyMeasures falling = world.assembly_measures();
  StageDef settle;
  settle.cycles = 100000;
  settle.until.kinetic_to_elastic_below = 1e-4;
  settle.until.unbalanced_force_below = 1e-3;
  settle.until.check_interval = 100;
  const StageResult result = run_stage(world, settle);
  const AssemblyMeasures settled = world.assembly_measures();
  std::printf("falling: KE/elastic %.3g, unbalanced %.3g, I %.3g; settled after %llu cycles: %.3g, %.3g, %.3g\n",
              falling.kinetic_to_elastic, falling.unbalanced_force, falling.inertial_number,
              static_cast<unsigned long long>(result.cycles_run), settled.kinetic_to_elastic, settled.unbalanced_force,
              settled.inertial_number);
  EXPECT_GT(falling.unbalanced_force, 0.1);
  EXPECT_GT(falling.kinetic_to_elastic, 1.0);
  ASSERT_TRUE(result.condition_met);
  EXPECT_LT(settled.kinetic_to_elastic, 1e-4);
  EXPECT_LT(settled.unbalanced_force, 1e-3);
  EXPECT_LT(settled.inertial_number, 1e-3);
  EXPECT_GT(settled.mean_stress, 0.0);
  EXPECT_GT(settled.elastic_energy, 0.0);
}

}  // namespace
}  // namespace dem
