// The list of contact laws (law_list.h, law_dispatch.h): each engine law's
// name and traits come from its type, and a law that lives only in these
// tests (frictionless_law.h) joins a list with one entry and is then
// dispatched, named, resolved, given its time step and run by the engine's
// contact row like the engine's own.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <type_traits>

#include "contact_row.h"
#include "critical_step.h"
#include "dem/error.h"
#include "dem/law_traits.h"
#include "dem/world.h"
#include "frictionless_law.h"
#include "law_dispatch.h"
#include "world_build.h"
#include "world_state.h"

namespace dem {
namespace {

using testing::FrictionlessLaw;
// The one entry a new law needs.
using TestLaws = ContactLaws::With<FrictionlessLaw>;
static_assert(distinct_laws(TestLaws{}));

TEST(LawList, EachEngineLawCarriesItsNameAndTraits) {
  const auto laws = contact_laws();
  ASSERT_EQ(laws.size(), 4U);
  const char* names[] = {"linear", "linear_restitution", "hertz_mindlin", "hertz_linear_tangential"};
  const bool hertz[] = {false, false, true, true};
  const bool normal_history[] = {true, false, true, false};
  const bool mindlin[] = {false, false, true, false};
  for (std::size_t k = 0; k < laws.size(); ++k) {
    EXPECT_STREQ(laws[k].name, names[k]);
    EXPECT_EQ(laws[k].hertz, hertz[k]) << names[k];
    EXPECT_EQ(is_hertz(laws[k].law), hertz[k]) << names[k];
    EXPECT_EQ(laws[k].normal_history, normal_history[k]) << names[k];
    EXPECT_EQ(laws[k].mindlin, mindlin[k]) << names[k];
    EXPECT_EQ(contact_law_named(names[k]), laws[k].law);
    EXPECT_STREQ(contact_law_name(laws[k].law), names[k]);
  }
  EXPECT_FALSE(laws[2].batchable);  // Mindlin's loading history branches per contact
  EXPECT_FALSE(contact_law_named("hooke").has_value());
}

TEST(LawList, ATestLawIsOneFileAndOneListEntry) {
  const auto traits = law_traits_of<TestLaws>(FrictionlessLaw::kLaw);
  ASSERT_TRUE(traits.has_value());
  EXPECT_STREQ(traits->name, "frictionless");
  EXPECT_FALSE(traits->hertz);
  EXPECT_FALSE(traits->normal_history);
  EXPECT_EQ(every_law(TestLaws{}).size(), 5U);
  // The dispatch reaches it, and still each engine law.
  bool frictionless = false, linear = false;
  with_law_of<TestLaws>(FrictionlessLaw::kLaw,
                        [&]<typename Law>() { frictionless = std::is_same_v<Law, FrictionlessLaw>; });
  with_law_of<TestLaws>(ContactLaw::kLinear, [&]<typename Law>() { linear = std::is_same_v<Law, LinearLaw>; });
  EXPECT_TRUE(frictionless);
  EXPECT_TRUE(linear);
  // The engine's own list does not hold it.
  EXPECT_FALSE(contact_law_traits(FrictionlessLaw::kLaw).has_value());
  EXPECT_STREQ(contact_law_name(FrictionlessLaw::kLaw), "unknown");
}

MaterialDef rubber() {
  MaterialDef m;
  m.name = "rubber";
  m.density = 1000.0;
  m.friction = 0.5;
  return m;
}

ContactModelDef frictionless_model() {
  ContactModelDef model;
  model.law = FrictionlessLaw::kLaw;
  model.linear = {2.0e5, 1.0e5};
  return model;
}

// Its parameter resolution runs after what every pair resolves: no shear
// spring and no friction, though the material has 0.5.
TEST(LawList, TheTestLawResolvesItsParameters) {
  DampingDef damping;
  damping.contact_beta = 1e-3;
  const ContactParams p = resolve_params<TestLaws>(rubber(), rubber(), frictionless_model(), damping);
  EXPECT_EQ(p.law, FrictionlessLaw::kLaw);
  EXPECT_EQ(p.normal_stiffness, 2.0e5);
  EXPECT_EQ(p.normal_viscosity, 1e-3 * 2.0e5);  // eq. 28, resolved for every law
  EXPECT_EQ(p.shear_stiffness, 0.0);
  EXPECT_EQ(p.friction, 0.0);
  // The engine's list resolves the same model as no law of its own: the common part only.
  EXPECT_EQ(resolve_params<ContactLaws>(rubber(), rubber(), frictionless_model(), damping).friction, 0.5);
}

// Its critical time step: the normal mode, 2 sqrt(m / k_n) undamped
// (Cundall & Strack, Motion), shortened by its dashpot.
TEST(LawList, TheTestLawGivesItsCriticalTimeStep) {
  DampingDef damping;
  damping.contact_beta = 1e-3;
  const MaterialDef material = rubber();
  const ContactParams p = resolve_params<TestLaws>(material, material, frictionless_model(), damping);
  const StepParticle particle{2.0, 0.5, 0.1, material};
  double undamped = 0.0, damped = 0.0;
  with_law_of<TestLaws>(p.law, [&]<typename Law>() {
    undamped = Law::undamped_critical_time_step(particle, p);
    damped = Law::critical_time_step(particle, p, damping);
  });
  EXPECT_DOUBLE_EQ(undamped, 2.0 * std::sqrt(2.0 / 2.0e5));
  const double zeta = p.normal_viscosity / (2.0 * std::sqrt(2.0e5 * 2.0));
  EXPECT_DOUBLE_EQ(damped, undamped * damped_step_factor(zeta));
}

// The engine's checks of a model know only the engine's laws.
TEST(LawList, AWorldRefusesALawItsListLacks) {
  WorldDef def;
  def.materials = {rubber()};
  def.contact_models = {frictionless_model()};
  def.particles = {ParticleDef{}};
  try {
    World world(def);
    ADD_FAILURE() << "a world was built with a law the engine lacks";
  } catch (const DefinitionError& e) {
    EXPECT_STREQ(e.what(), "contact model 0: unknown contact law 41");
  }
}

// Two discs pressed 1 mm together and sliding past each other: the
// engine's contact row (contact_row.h, the body the force pass and the
// reports share) runs the test's law: F_n = k_n delta + c_n delta_dot along
// the line of centres, and no tangential force.
TEST(LawList, TheEngineContactRowRunsTheTestLaw) {
  WorldDef def;
  def.materials = {rubber()};
  ContactModelDef linear = frictionless_model();
  linear.law = ContactLaw::kLinear;  // what the engine's checks accept; the table below takes the test's
  def.contact_models = {linear};
  def.damping.contact_beta = 1e-3;
  ParticleDef a, b;
  a.radius = b.radius = 0.1;
  b.position = Vec2(0.199, 0.0);
  a.velocity = Vec2(0.01, 0.02);  // approaching at 0.01 m/s and sliding at 0.02 m/s
  def.particles = {a, b};
  WorldState<2> s;
  build_world(s, def);
  s.params = ContactParamTable(s.materials, {frictionless_model()}, s.damping, &resolve_params<TestLaws>);
  const StepContext now = current_context(s);
  find_contacts(s, now);
  ASSERT_EQ(s.contacts.pairs.size(), 1U);
  const PassInputs<2> in{s.particles, s.walls, s.periodic, s.params, nullptr, nullptr, 1e-4, 0, near_margin(s)};
  ContactEnergy energy;
  const RowResult<2> row =
      contact_row<Pass::kAdvance, false, FrictionlessLaw, RoundShape, ParticleBody<2>>(in, s.contacts.pairs, 0, energy);
  ASSERT_TRUE(row.touching);
  const double normal = 2.0e5 * 1e-3 + 1e-3 * 2.0e5 * 0.01;
  EXPECT_NEAR(row.force.x(), -normal, 1e-9 * normal);
  EXPECT_EQ(row.force.y(), 0.0);
  EXPECT_TRUE(s.contacts.pairs.touching(0));
}

}  // namespace
}  // namespace dem
