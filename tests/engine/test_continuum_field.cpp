// Randall's (1989) continuum strain-rate control, 4.5.2 (after Cundall
// 1988): a box with `continuum` carries its particles with the homogeneous
// velocity field of its axis rates (eqs. 4.41, 4.43-4.44), the contacts see
// the field's relative velocity e_ij z_j (eq. 4.42), its work is booked in
// the energy budget, and restart and threads stay exact with it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "dem/error.h"
#include "dem/packing.h"
#include "dem/world.h"
#include "exact_continuation.h"
#include "model_builders.h"

namespace dem {
namespace {

// A 0.2 m box of four walls, 0 bottom, 1 right, 2 top, 3 left, around the
// given discs; a linear law, friction 0.5, no gravity, no damping.
WorldDef box_around(std::vector<ParticleDef> particles) {
  WorldDef def;
  def.materials = {MaterialDef{"disc", 2650.0, 0.5, 0.0}};
  def.contact_models = {testing::linear_model(1e6, 1e6)};
  def.particles = std::move(particles);
  def.walls = {WallDef{"bottom", {0.1, 0.0}, {1, 0}, -0.2, 0.2, MaterialId{0}, {}},
               WallDef{"right", {0.2, 0.1}, {0, 1}, -0.2, 0.2, MaterialId{0}, {}},
               WallDef{"top", {0.1, 0.2}, {-1, 0}, -0.2, 0.2, MaterialId{0}, {}},
               WallDef{"left", {0.0, 0.1}, {0, -1}, -0.2, 0.2, MaterialId{0}, {}}};
  def.fixed_time_step = 1e-4;
  def.threads = 1;
  return def;
}

// Strain rates on the box's axes (compression positive), the particles
// carried by the field when `continuum`.
BoxControl rates(double x, double y, bool continuum) {
  BoxControl control;
  control.axes[0] = BoxAxisDef{WallId{3}, WallId{1}, AxisControl::kStrainRate, x, 0.0};
  control.axes[1] = BoxAxisDef{WallId{0}, WallId{2}, AxisControl::kStrainRate, y, 0.0};
  control.continuum = continuum;
  return control;
}

ParticleDef disc(Vec2 x, double radius) { return ParticleDef{x, radius, MaterialId{0}, {0.0, 0.0}, 0.0}; }

// Eq. 4.41: with nothing touching, the particles move with the field alone,
// so each keeps its place relative to the box as the box deforms.
TEST(ContinuumField, ParticlesApartFollowTheBoxsDeformation) {
  RandomPackingDef packing;
  packing.min = {0.02, 0.02};
  packing.max = {0.18, 0.18};
  packing.sizes = {{0.003, 30}};
  packing.seed = 4;
  World world(box_around(generate_random_packing(packing)));
  world.set_box_control(rates(-2.0, 1.0, true));
  auto relative = [&](const World& w) {
    std::vector<Vec2> r;
    const BoxMeasure m = w.box_measure();
    const Vec2 low{w.wall(WallId{3}).point.x(), w.wall(WallId{0}).point.y()};
    for (const Vec2& x : w.particles().position) r.emplace_back((x - low).cwiseQuotient(m.extent));
    return r;
  };
  ASSERT_EQ(world.contacts().size(), 0u);
  const std::vector<Vec2> before = relative(world);
  world.cycle(5000);
  const std::vector<Vec2> after = relative(world);
  double worst = 0.0;
  for (std::size_t i = 0; i < before.size(); ++i) worst = std::max(worst, (after[i] - before[i]).norm());
  const BoxMeasure m = world.box_measure();
  std::printf(
      "after 5000 steps at rates -2, 1 /s: box %.6f x %.6f m, no contacts %zu, worst drift of a particle's "
      "place in the box %.2e\n",
      m.extent.x(), m.extent.y(), world.contacts().size(), worst);
  EXPECT_GT(m.extent.x(), 0.2 * 1.2);  // the box did deform
  EXPECT_EQ(world.contacts().size(), 0u);
  EXPECT_LT(worst, 1e-12);
}

// Eq. 4.42: a contact's relative velocity is the particles' own plus the
// field's e_ij z_j. Two discs touching along a diagonal under a pure shear
// field (extension along x, compression along y) see a purely tangential
// relative velocity of |e| |z|: one step gives a shear force of
// k_s |e| |z| dt. Without the field the walls alone move and the discs, far
// from them, feel nothing.
TEST(ContinuumField, ContactsSeeTheFieldsRelativeVelocity) {
  const double radius = 0.01, overlap = 1e-5, rate = 1.0;  // m, m, 1/s
  const Vec2 centre{0.1, 0.1};
  const double half = 0.5 * (2.0 * radius - overlap) / std::sqrt(2.0);
  const std::vector<ParticleDef> pair = {disc(centre - Vec2{half, half}, radius),
                                         disc(centre + Vec2{half, half}, radius)};
  for (const bool continuum : {true, false}) {
    World world(box_around(pair));
    world.set_box_control(rates(-rate, rate, continuum));
    world.cycle();
    const auto contacts = world.contacts();
    ASSERT_EQ(contacts.size(), 1u);
    const double expected = continuum ? 1e6 * rate * (2.0 * radius - overlap) * world.time_step() : 0.0;
    std::printf("%s: shear force %.9e N (k_s |e| |z| dt = %.9e), normal force %.6e N\n",
                continuum ? "with the field" : "walls alone", std::abs(contacts[0].shear_force), expected,
                contacts[0].normal_force);
    // Within terms of order e dt (1e-4): the pair turns as it shears.
    EXPECT_NEAR(std::abs(contacts[0].shear_force), expected, 1e-4 * 1e6 * rate * 2.0 * radius * world.time_step());
    EXPECT_GT(contacts[0].normal_force, 0.0);
  }
}

// 200 discs in a 0.2 m box, dashpots at the contacts and CON1-like global
// damping of the particles' own velocities, compressed by the box and its
// field (Randall 6.4.3's preparation).
WorldDef compressed_packing() {
  RandomPackingDef packing;
  packing.min = {0.0, 0.0};
  packing.max = {0.2, 0.2};
  packing.sizes = {{0.006, 80}, {0.0045, 120}};
  packing.seed = 3;
  WorldDef def = box_around(generate_random_packing(packing));
  def.contact_models[0].law = ContactLaw::kLinearRestitution;
  def.contact_models[0].restitution = 0.5;
  def.damping.global_alpha = 20.0;
  def.energy_budget = true;
  def.box_control = rates(1.0, 1.0, true);
  return def;
}

// The field's work goes into the budget: what came in (the walls' and the
// field's work) is what is held and dissipated, up to the integration
// error, which the field does not enlarge: the same compression by the
// walls alone leaves the same residual (both shrink as dt: measured 2.5e-3,
// 1.2e-3 and 6e-4 of the work at 1e-4, 5e-5 and 2.5e-5 s, with the field
// or without).
TEST(ContinuumField, ItsWorkClosesTheEnergyBudget) {
  double residual[2] = {0.0, 0.0};
  for (const bool continuum : {true, false}) {
    WorldDef def = compressed_packing();
    def.box_control->continuum = continuum;
    World world(def);
    world.cycle(3500);
    const EnergyBudget e = world.assembly_measures().energy;
    const double in = std::abs(e.wall_work) + std::abs(e.continuum_work);
    residual[continuum ? 0 : 1] = std::abs(e.residual()) / in;
    std::printf(
        "%s, after 3500 steps: box %.5f m, %zu contacts; continuum work %.6e J, wall work %.6e J, kinetic "
        "%.3e, strain %.3e, dashpots %.3e, global damping %.3e, friction %.3e J; residual %.3e J (%.2e of the "
        "work done)\n",
        continuum ? "with the field" : "walls alone", world.box_measure().extent.x(), world.contacts().size(),
        e.continuum_work, e.wall_work, e.kinetic, e.strain, e.contact_damping, e.global_damping, e.friction,
        e.residual(), residual[continuum ? 0 : 1]);
    EXPECT_GT(world.contacts().size(), 300u);  // compressed well into contact
    if (continuum) {
      EXPECT_NE(e.continuum_work, 0.0);
    }
  }
  EXPECT_LT(residual[0], 5e-3);
  EXPECT_LT(residual[0], 1.5 * residual[1]);
}

// Restart is bit-exact in the middle of a continuum compression (the field
// the velocities carry is part of the state), and two threads agree.
TEST(ContinuumField, RestartAndThreadsStayExact) {
  testing::expect_exact_continuation(compressed_packing(), 2000, 2000, "continuum compression");
}

// The field's state and the box's flag change the state hash.
TEST(ContinuumField, TheHashSeesTheField) {
  WorldDef def = compressed_packing();
  World with(def);
  def.box_control->continuum = false;
  World without(def);
  with.cycle(10);
  without.cycle(10);
  EXPECT_NE(with.state_hash(), without.state_hash());
}

TEST(ContinuumField, NotWithPeriodicBoundaries) {
  WorldDef def = compressed_packing();
  def.periodic.axes = {true, false};
  def.periodic.min = {0.0, 0.0};
  def.periodic.max = {0.2, 0.0};
  std::string message;
  try {
    World world(def);
  } catch (const DefinitionError& e) {
    message = e.what();
  }
  EXPECT_EQ(message, "box control: continuum is not available with periodic boundaries");
}

}  // namespace
}  // namespace dem
