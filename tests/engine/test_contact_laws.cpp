// The contact laws as small, separately testable pieces: driven through
// ContactDriver, and their rules at World construction.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dem/contact_driver.h"
#include "dem/error.h"
#include "dem/world.h"
#include "mindlin.h"
#include "model_builders.h"

namespace dem {
namespace {

MaterialDef steel() {
  MaterialDef m;
  m.name = "steel";
  m.density = 7800.0;
  m.friction = 0.3;
  m.youngs_modulus = 210e9;
  m.poisson_ratio = 0.3;
  return m;
}

ContactDriverDef hertz_pair(ContactLaw law) {
  ContactDriverDef def;
  def.material_a = def.material_b = steel();
  def.model.law = law;
  def.radius_a = def.radius_b = 0.01;
  return def;
}

TEST(ContactLaws, HertzNormalForceFollowsRandall3_13) {
  ContactDriver contact(hertz_pair(ContactLaw::kHertzLinearTangential));
  const double e_star = 210e9 / (2.0 * (1.0 - 0.09)), r_star = 0.005;
  for (int k = 0; k < 100; ++k) {
    contact.step(1e-7, 0.0, 1e-6);
    const double alpha = contact.overlap();
    EXPECT_NEAR(contact.normal_force(), 4.0 / 3.0 * e_star * std::sqrt(r_star * alpha * alpha * alpha),
                1e-9 * contact.normal_force());
  }
  EXPECT_NEAR(contact.contact_radius(), std::sqrt(r_star * contact.overlap()), 1e-15);
}

TEST(ContactLaws, LinearPressureTangentialStiffnessIs8GStarA) {
  ContactDriver contact(hertz_pair(ContactLaw::kHertzLinearTangential));
  for (int k = 0; k < 100; ++k) contact.step(1e-7, 0.0, 1e-6);
  const double g_star = 210e9 / (4.0 * (2.0 - 0.3) * 1.3);
  const double a = contact.contact_radius();
  contact.step(0.0, 1e-9, 1e-6);
  EXPECT_NEAR(contact.tangential_force(), 8.0 * g_star * a * 1e-9, 1e-9 * contact.tangential_force());  // Miyata 31
}

TEST(ContactLaws, MindlinReversalPointsAndSlidingErasure) {
  MindlinHistory h;
  double T = 0.0;
  const double N = 100.0, a = 1e-4, mu = 0.5, g = 1e10;
  for (int k = 0; k < 10; ++k) mindlin_step(h, T, N, 0.0, a, 1e-8, mu, g);  // virgin loading
  EXPECT_EQ(h.direction, 1.0);
  EXPECT_FALSE(h.unloading);
  const double peak = T;
  mindlin_step(h, T, N, 0.0, a, -1e-8, mu, g);  // reversal: unloading starts at T* = peak
  EXPECT_TRUE(h.unloading);
  EXPECT_EQ(h.t_star, peak);
  mindlin_step(h, T, N, 0.0, a, 1e-9, mu, g);  // reversal again: reloading from T**
  EXPECT_TRUE(h.reloading);
  // Unloading stiffness starts at 8 G* a (theta = 1 at the reversal, Randall 3.54).
  MindlinHistory fresh = h;
  double t = T;
  const double before = t;
  mindlin_step(fresh, t, N, 0.0, a, -1e-12, mu, g);
  EXPECT_TRUE(fresh.reloading);  // a re-unloading step inside the loop keeps T**
  EXPECT_NEAR(before - t, 8.0 * g * a * 1e-12, 1e-3 * 8.0 * g * a * 1e-12);
  mindlin_slide(h, -mu * N);
  EXPECT_EQ(h.direction, -1.0);
  EXPECT_FALSE(h.unloading || h.reloading);
}

WorldDef two_materials(ContactLaw pair_law, ContactLaw wall_law) {
  WorldDef def;
  def.materials = {steel(), steel()};
  def.materials[1].name = "steel2";
  ContactModelDef pp = testing::linear_model(1e6, 1e6, MaterialId{0}, MaterialId{0}),
                  pq = testing::linear_model(1e6, 1e6, MaterialId{0}, MaterialId{1}),
                  qq = testing::linear_model(1e6, 1e6, MaterialId{1}, MaterialId{1});
  pp.law = pair_law;
  qq.law = pair_law;
  pq.law = wall_law;
  def.contact_models = {pp, pq, qq};
  def.particles = {ParticleDef{{0.0, 0.0}, 0.01, MaterialId{0}}, ParticleDef{{0.1, 0.0}, 0.01, MaterialId{0}}};
  def.walls = {WallDef{"floor", {0.0, -0.01}, {1.0, 0.0}, -1.0, 1.0, MaterialId{1}, {}}};
  return def;
}

TEST(ContactLaws, ParticlePairsAndWallsMayUseDifferentLaws) {
  EXPECT_NO_THROW(World(two_materials(ContactLaw::kHertzMindlin, ContactLaw::kLinear)));
  WorldDef mixed = two_materials(ContactLaw::kLinear, ContactLaw::kLinear);
  mixed.particles[1].material = MaterialId{1};  // particle-particle pairs now meet two laws
  mixed.contact_models[2].law = ContactLaw::kHertzMindlin;
  try {
    World world(mixed);
    FAIL() << "mixed particle-particle laws accepted";
  } catch (const DefinitionError& e) {
    EXPECT_NE(std::string(e.what()).find("particle-particle contacts must all use one contact law"), std::string::npos)
        << e.what();
  }
}

TEST(ContactLaws, HertzNeedsElasticConstantsAndUsesRayleighStep) {
  WorldDef def = two_materials(ContactLaw::kHertzMindlin, ContactLaw::kHertzMindlin);
  def.time_step_fraction = 0.5;
  World world(def);
  // Randall 4.33-4.34 for the particle: pi R sqrt(rho / G) / (0.1631 nu + 0.876605).
  const double g = 210e9 / 2.6;
  const double rayleigh = std::numbers::pi * 0.01 * std::sqrt(7800.0 / g) / (0.1631 * 0.3 + 0.876605);
  EXPECT_NEAR(world.critical_time_step(), rayleigh, 1e-12 * rayleigh);
  EXPECT_NEAR(world.time_step(), 0.5 * rayleigh, 1e-12 * rayleigh);
  def.materials[0].youngs_modulus = 0.0;
  EXPECT_THROW(World{def}, DefinitionError);
}

}  // namespace
}  // namespace dem
