// Cundall & Strack (1979) force-displacement law: the hand calculation of
// Fig. 1 (eqs. 1-7), the Coulomb limit (eq. 19) and contact damping (26-28).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "dem/world.h"
#include "model_builders.h"

namespace dem {
namespace {

constexpr double kRadius = 1.0;
constexpr double kStiffness = 1.0e6;
constexpr double kDensity = 1.0;
constexpr double kWallSpeed = 0.01;
constexpr double kTimeStep = 1.0e-4;

// Fig. 1: two discs x and y squashed between walls moving towards each other
// at speed v. At t0 everything touches and no force exists.
WorldDef two_discs_between_walls() {
  WorldDef def;
  def.materials = {MaterialDef{"disc", kDensity, 0.0, 0.0}};
  def.contact_models = {testing::linear_model(kStiffness, kStiffness, MaterialId{0}, MaterialId{0})};
  def.particles = {ParticleDef{{kRadius, 0.0}, kRadius, MaterialId{0}},
                   ParticleDef{{3.0 * kRadius, 0.0}, kRadius, MaterialId{0}}};
  WallDef left{"left", {0.0, 0.0}, {0.0, -1.0}, -2.0, 2.0, MaterialId{0}, {}};  // normal points to +1
  WallDef right{"right", {4.0 * kRadius, 0.0}, {0.0, 1.0}, -2.0, 2.0, MaterialId{0}, {}};
  left.motion.velocity = {kWallSpeed, 0.0};
  right.motion.velocity = {-kWallSpeed, 0.0};
  def.walls = {left, right};
  def.fixed_time_step = kTimeStep;
  return def;
}

TEST(ContactLaw, Fig1HandCalculationOfTheFirstCycles) {
  World world(two_discs_between_walls());
  const double m = kDensity * std::numbers::pi * kRadius * kRadius;
  const double v = kWallSpeed, dt = kTimeStep, k = kStiffness;

  // Cycle 0: everything touches, nothing overlaps (eq. 8 is strict).
  ASSERT_TRUE(world.contacts().empty());

  // The hand calculation, eqs. 2-7: forces from the accumulated relative
  // displacements, velocities from Newton's second law over each step.
  double force_a = 0.0, force_b = 0.0, force_c = 0.0;  // contacts A (left wall), B (discs), C (right wall)
  double velocity_x = 0.0, velocity_y = 0.0;
  for (int cycle = 1; cycle <= 6; ++cycle) {
    // The walls and discs move over one step at the velocities of the
    // last one; the forces follow from the new relative displacements.
    world.cycle();
    force_a += k * (v - velocity_x) * dt;           // eq. 2 with eq. 5
    force_b += k * (velocity_x - velocity_y) * dt;  // eq. 6
    force_c += k * (v + velocity_y) * dt;           // eq. 7
    double engine_a = 0.0, engine_b = 0.0, engine_c = 0.0;
    for (const ContactRecord& c : world.contacts()) {
      if (c.second_wall == WallId{0}) engine_a = c.normal_force;
      if (c.second_wall == WallId{1}) engine_c = c.normal_force;
      if (c.second_particle == ParticleId{1}) engine_b = c.normal_force;
    }
    // Round-off: overlaps come from R_x + R_y - D with D about 2 R, so each
    // carries an absolute error of a few ulps of 4 R.
    const double overlap_roundoff = 4.0 * kRadius * 4.0 * std::numeric_limits<double>::epsilon();
    const double tol = k * overlap_roundoff * cycle;
    EXPECT_NEAR(engine_a, force_a, tol) << "contact A, cycle " << cycle;
    EXPECT_NEAR(engine_b, force_b, tol) << "contact B, cycle " << cycle;
    EXPECT_NEAR(engine_c, force_c, tol) << "contact C, cycle " << cycle;
    // The velocities over the step just taken came from the last cycle's force sums.
    EXPECT_NEAR(world.particles().velocity[ParticleId{0}].x(), velocity_x, 2.0 * tol / m * dt * cycle)
        << "cycle " << cycle;
    EXPECT_NEAR(world.particles().velocity[ParticleId{1}].x(), velocity_y, 2.0 * tol / m * dt * cycle)
        << "cycle " << cycle;
    std::printf("cycle %d: F_A=%.6e F_B=%.6e F_C=%.6e (hand: %.6e %.6e %.6e)\n", cycle, engine_a, engine_b, engine_c,
                force_a, force_b, force_c);
    velocity_x += (force_a - force_b) / m * dt;  // eqs. 2-4: force sums, then Newton's second law
    velocity_y += (force_b - force_c) / m * dt;
  }
}

// A disc dragged by a moving floor into a fixed side wall: it cannot roll on
// both, so a contact slides, and its shear force reaches but never exceeds
// (F_s)max = F_n tan(phi) + c.
WorldDef disc_dragged_into_corner(double disc_friction, double wall_friction, double cohesion) {
  WorldDef def;
  def.materials = {MaterialDef{"disc", 1000.0, disc_friction, cohesion},
                   MaterialDef{"floor", 1.0, wall_friction, 2.0 * cohesion}};
  def.contact_models = {testing::linear_model(1.0e7, 0.8e7)};
  def.particles = {ParticleDef{{0.0, 0.1}, 0.1, MaterialId{0}}};
  WallDef floor{"floor", {0.0, 0.0}, {1.0, 0.0}, -100.0, 100.0, MaterialId{1}, {}};
  WallDef side{"side", {0.1, 0.0}, {0.0, 1.0}, 0.0, 100.0, MaterialId{1}, {}};
  floor.motion.velocity = {0.5, 0.0};
  def.walls = {floor, side};
  def.gravity = {5.0, -9.81};  // tilted: the disc leans on the side wall
  def.damping.contact_beta = 1e-4;
  def.time_step_fraction = 0.1;
  return def;
}

TEST(ContactLaw, CoulombLimitWithCohesionIsNeverExceeded) {
  const double cohesion = 5.0;
  World world(disc_dragged_into_corner(0.45, 0.17, cohesion));
  int sliding_cycles = 0;
  double worst_ratio = 0.0;
  for (int cycle = 0; cycle < 20000; ++cycle) {
    world.cycle();
    for (const ContactRecord& c : world.contacts()) {
      // eq. 19: the smaller friction (0.17) and the smaller cohesion of the pair.
      const double limit = c.normal_force * 0.17 + cohesion;
      EXPECT_LE(std::abs(c.shear_force), limit * (1.0 + 1e-12));
      worst_ratio = std::max(worst_ratio, std::abs(c.shear_force) / limit);
      if (c.sliding) {
        ++sliding_cycles;
        EXPECT_EQ(c.shear_damping, 0.0) << "a sliding contact carries no shear dashpot";
        EXPECT_NEAR(std::abs(c.shear_force), limit, 1e-9 * limit);
      }
    }
  }
  std::printf("sliding cycles %d, largest |F_s|/(F_s)max %.15f\n", sliding_cycles, worst_ratio);
  EXPECT_GT(sliding_cycles, 1000) << "the test must exercise the sliding branch";
}

TEST(ContactLaw, StickingContactCarriesShearDashpot) {
  World world(disc_dragged_into_corner(5.0, 5.0, 0.0));  // friction too high to slide
  world.cycle(50);
  const auto contacts = world.contacts();
  ASSERT_FALSE(contacts.empty());
  for (const ContactRecord& c : contacts) {
    EXPECT_FALSE(c.sliding);
    EXPECT_NE(c.shear_damping, 0.0) << "eq. 27: c_s s_dot acts while the contact sticks";
  }
}

}  // namespace
}  // namespace dem
