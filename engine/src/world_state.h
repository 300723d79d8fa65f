// Everything a World owns. Internal to the engine.
#pragma once

#include <cstdint>
#include <vector>

#include "contact_params.h"
#include "contact_table.h"
#include "dem/definitions.h"
#include "dem/profile.h"
#include "particles.h"
#include "walls.h"

namespace dem {

struct WorldState {
  std::vector<MaterialDef> materials;
  std::vector<ContactModelDef> contact_models;
  Particles particles;
  Walls walls;
  ContactTable contacts;
  ContactParamTable params;
  DampingDef damping;
  Vec2 gravity = Vec2::Zero();
  double time_step = 0.0;
  double critical_time_step = 0.0;
  double time_step_fraction = 0.1;  // the user's settings the step came from
  double fixed_time_step = 0.0;
  double contact_tolerance = 0.0;  // BALL's TOL
  int threads = 1;
  std::uint64_t cycle = 0;
  double time = 0.0;
  // Neighbour-list bookkeeping: positions at the last rebuild and how far
  // particles and walls have moved since.
  std::vector<Vec2> reference_positions;
  double particle_travel = 0.0;
  double wall_travel = 0.0;
  bool contacts_stale = true;
  StepProfile profile;
};

// Rebuilds the contact table from the broad phase (keeping history).
void find_contacts(WorldState& state);

// Critical time step 2 sqrt(m/k) over particles and the stiffnesses they can meet.
double estimate_critical_time_step(const WorldState& state);

}  // namespace dem
