// The critical time step (time_step.cpp) against the closed form of the
// central-difference scheme with a dashpot on the last step's velocity,
// omega dt < 2 (sqrt(1 + zeta^2) - zeta), on a single damped contact: a
// disc resting on a wall under gravity, started a little off its
// equilibrium, oscillates on the one contact. Just below the limit the
// oscillation dies away; just above it grows every step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "critical_step.h"
#include "dem/world.h"
#include "model_builders.h"
#include "world_state.h"

namespace dem {
namespace {

constexpr double kNormalStiffness = 1.0e6;
constexpr double kRadius = 0.5;
constexpr double kDensity = 1000.0;
const double kMass = kDensity * std::numbers::pi * kRadius * kRadius;  // a disc of unit depth

// The disc on the floor, its overlap `offset` beyond the equilibrium
// overlap m g / k_n. The shear spring is soft, so the normal translation
// is the stiffest mode (rotation: omega^2 = 2 k_s / m = 0.2 k_n / m).
WorldDef disc_on_floor(const DampingDef& damping, double offset) {
  WorldDef def;
  def.materials = {MaterialDef{"disc", kDensity, 0.5, 0.0}};
  def.contact_models = {testing::linear_model(kNormalStiffness, 0.1 * kNormalStiffness)};
  const double rest_overlap = kMass * 9.81 / kNormalStiffness;
  ParticleDef disc;
  disc.radius = kRadius;
  disc.position = {0.0, kRadius - rest_overlap - offset};
  def.particles = {disc};
  def.walls = {WallDef{"floor", {0, 0}, {1, 0}, -5, 5, MaterialId{0}, {}}};
  def.gravity = {0.0, -9.81};
  def.damping = damping;
  def.threads = 1;
  return def;
}

// The closed form for the disc's normal mode: omega = sqrt(k_n / m),
// zeta = c / (2 sqrt(k_n m)) with c = beta k_n (Cundall & Strack eq. 28).
double closed_form_step(double beta) {
  const double omega = std::sqrt(kNormalStiffness / kMass);
  const double zeta = beta * kNormalStiffness / (2.0 * std::sqrt(kNormalStiffness * kMass));
  return 2.0 / omega * (std::sqrt(1.0 + zeta * zeta) - zeta);
}

// How far the disc is from its equilibrium after `cycles` steps of
// `fraction` of the critical step, over how far it started.
double amplitude_ratio(const DampingDef& damping, double fraction, int cycles) {
  const double offset = 1e-6 * kRadius;
  WorldDef def = disc_on_floor(damping, offset);
  def.fixed_time_step = fraction * World(def).critical_time_step();
  World world(def);
  const double rest = kRadius - kMass * 9.81 / kNormalStiffness;
  world.cycle(static_cast<std::uint64_t>(cycles));
  const double y = world.particles().position[ParticleId{0}].y();
  return std::abs(y - rest) / offset;
}

// 0.98 of the limit settles; 1.02 of it grows more than `growth` times in 400 steps.
void expect_stable_below_and_growing_above(const DampingDef& damping, const char* what, double growth) {
  const double below = amplitude_ratio(damping, 0.98, 400);
  const double above = amplitude_ratio(damping, 1.02, 400);
  std::printf("%s, 400 steps: amplitude x %.3g at 0.98 of the limit, x %.3g at 1.02\n", what, below, above);
  EXPECT_LT(below, 1.0);
  EXPECT_GT(above, growth);
}

TEST(TimeStep, TheCriticalStepOfOneDampedContactIsTheClosedForm) {
  for (const double beta : {0.0, 1e-3, 5e-3, 2e-2}) {
    DampingDef damping;
    damping.contact_beta = beta;
    const World world(disc_on_floor(damping, 0.0));
    const double expected = closed_form_step(beta);
    std::printf("contact beta %g s: critical step %.6g s, closed form %.6g s (zeta %.3f)\n", beta,
                world.critical_time_step(), expected,
                beta * kNormalStiffness / (2.0 * std::sqrt(kNormalStiffness * kMass)));
    EXPECT_NEAR(world.critical_time_step(), expected, 1e-12 * expected);
    EXPECT_NEAR(world.critical_time_step_with(damping), expected, 1e-12 * expected);
  }
}

// The scheme itself: 0.98 of the damped limit settles, 1.02 of it blows up
// (without the damping in the limit, 0.98 of the undamped one would pass
// for stable at zeta = 0.36: it is 1.38 of the damped limit).
TEST(TimeStep, OneDampedContactIsStableBelowTheDampedLimitAndGrowsAbove) {
  DampingDef damping;
  damping.contact_beta = 2e-2;
  expect_stable_below_and_growing_above(damping, "contact damping, zeta 0.36", 100.0);
}

// Global damping (eq. 34) taken at the middle of the step (eqs. 35-36)
// leaves the limit at omega dt = 2: strong global damping alone does not
// shorten the critical step, and 0.98 of it still settles.
TEST(TimeStep, CentredGlobalDampingLeavesTheLimitWhereItWas) {
  DampingDef damping;
  damping.global_alpha = 0.5 * std::sqrt(kNormalStiffness / kMass);  // C = alpha m: zeta 0.25
  const World world(disc_on_floor(damping, 0.0));
  EXPECT_NEAR(world.critical_time_step(), closed_form_step(0.0), 1e-12 * closed_form_step(0.0));
  expect_stable_below_and_growing_above(damping, "global damping, zeta 0.25 (limit omega dt = 2)", 100.0);
}

// Local damping (Miyata eq. 33) stiffens the spring by 1 + alpha while it
// holds the disc back: the limit is 2 / sqrt(1 + alpha) of the undamped one.
TEST(TimeStep, LocalDampingShortensTheLimitBySqrtOnePlusAlpha) {
  DampingDef damping;
  damping.local_alpha = 0.3;
  const World world(disc_on_floor(damping, 0.0));
  const double expected = closed_form_step(0.0) / std::sqrt(1.3);
  EXPECT_NEAR(world.critical_time_step(), expected, 1e-12 * expected);
  expect_stable_below_and_growing_above(damping, "local damping 0.3", 100.0);
}

// The factor alone: 1 undamped, 2 (sqrt(1 + zeta^2) - zeta) -> 1/zeta for heavy damping.
TEST(TimeStep, TheDampedFactorIsOneUndampedAndFallsAsOneOverTwoZeta) {
  EXPECT_DOUBLE_EQ(damped_step_factor(0.0), 1.0);
  EXPECT_NEAR(damped_step_factor(0.1), std::sqrt(1.01) - 0.1, 1e-15);
  EXPECT_NEAR(damped_step_factor(100.0) * 200.0, 1.0, 1e-4);
}

// A stage's or a parameter's damping moves the critical step; the step
// stays, a fraction being of the undamped critical step.
TEST(TimeStep, NewDampingMovesTheCriticalStepNotTheStep) {
  WorldDef def = disc_on_floor({}, 0.0);
  def.time_step_fraction = 0.5;
  World world(def);
  EXPECT_NEAR(world.undamped_critical_time_step(), closed_form_step(0.0), 1e-15);
  DampingDef damping;
  damping.contact_beta = 2e-2;
  world.set_damping(damping);
  EXPECT_NEAR(world.critical_time_step(), closed_form_step(2e-2), 1e-12);
  EXPECT_NEAR(world.undamped_critical_time_step(), closed_form_step(0.0), 1e-15);
  EXPECT_NEAR(world.time_step(), 0.5 * closed_form_step(0.0), 1e-15);
  world.set_time_step_fraction(0.5);
  EXPECT_NEAR(world.time_step(), 0.5 * closed_form_step(0.0), 1e-15);
}

}  // namespace
}  // namespace dem
