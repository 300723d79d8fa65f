// Worlds with rich state for the snapshot tests of the engine and of io:
// contact history, sliding, wall motion and a servo in 2D; Hertz-Mindlin
// history, vector spins and quaternions in 3D.
#pragma once

#include "dem/packing.h"
#include "dem/world.h"
#include "model_builders.h"

namespace dem::testing {

// Discs settling in a box whose lid is a servo (BALL's linear law).
inline WorldDef settling_box() {
  WorldDef def;
  def.materials = {MaterialDef{"disc", 2650.0, 0.4, 0.0}, MaterialDef{"wall", 1.0, 0.2, 0.0}};
  def.contact_models = {linear_model(1.0e6, 0.7e6)};
  def.contact_models[0].friction = 0.35;
  RandomPackingDef packing;
  packing.min = {0.0, 0.0};
  packing.max = {0.3, 0.3};
  packing.sizes = {{0.012, 40}, {0.008, 60}};
  packing.seed = 11;
  def.particles = generate_random_packing(packing);
  def.walls = {WallDef{"bottom", {0.15, 0.0}, {1, 0}, -0.2, 0.2, MaterialId{1}, {}},
               WallDef{"right", {0.3, 0.15}, {0, 1}, -0.2, 0.2, MaterialId{1}, {}},
               WallDef{"top", {0.15, 0.3}, {-1, 0}, -0.2, 0.2, MaterialId{1}, {}},
               WallDef{"left", {0.0, 0.15}, {0, -1}, -0.2, 0.2, MaterialId{1}, {}}};
  def.walls[2].motion.servo = ServoDef{200.0, 1e-3, 0.05};
  def.walls[3].motion.velocity = {0.001, 0.0};
  def.gravity = {0.0, -9.81};
  def.damping = {1e-4, 0.5};
  def.threads = 1;
  def.energy_budget = true;  // the dashpot-work columns restore too
  return def;
}

// A small stack of steel spheres on a floor.
inline WorldDef3 sphere_stack(ContactLaw law) {
  WorldDef3 def;
  def.materials = {MaterialDef{"steel", 7800.0, 0.3, 0.0, 210e9, 0.3}, MaterialDef{"wall", 1.0, 0.2, 0.0, 0.0, 0.0}};
  ContactModelDef model;
  model.law = law;
  model.linear = {1.0e5, 0.8e5};  // the linear laws'
  model.hertz.damping_ratio = 0.05;
  model.hertz.restitution = 0.8;
  def.contact_models = {model};
  LatticeDef3 lattice;
  lattice.radius = 0.004;
  lattice.spacing = 0.008;
  lattice.origin = {0.01, 0.01, 0.004};
  lattice.columns = lattice.rows = lattice.layers = 3;
  def.particles = generate_lattice(lattice);
  // The Hertz stack is grown by 10 micrometres once placed, so it starts in
  // contact: its steps are a fraction of a microsecond and gravity alone
  // would take long to press it together. The linear stack just touches.
  if (law != ContactLaw::kLinear) {
    for (ParticleDef3& p : def.particles) p.radius += 1e-5;
  }
  for (std::size_t i = 0; i < def.particles.size(); i += 2) def.particles[i].velocity = {0.01, -0.02, 0.0};
  WallDef3 floor;
  floor.name = "floor";
  floor.point = {0.02, 0.02, 0.0};
  floor.direction = Vec3::UnitX();
  floor.direction2 = Vec3::UnitY();
  floor.h1 = floor.k1 = -0.05;
  floor.h2 = floor.k2 = 0.05;
  floor.material = MaterialId{1};
  floor.motion.velocity = {0.0, 0.0, 0.001};
  def.walls = {floor};
  def.gravity = {0.0, 0.0, -9.81};
  def.time_step_fraction = 0.2;
  def.threads = 1;
  def.energy_budget = true;
  return def;
}

}  // namespace dem::testing
