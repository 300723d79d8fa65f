// Everything a World owns, and the engine-internal functions over it.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "contact_params.h"
#include "contact_table.h"
#include "dem/definitions.h"
#include "dem/measures.h"
#include "dem/profile.h"
#include "dem/snapshot.h"
#include "particles.h"
#include "periodic.h"
#include "walls.h"

namespace dem {

template <int Dim>
struct WorldState {
  std::vector<MaterialDef> materials;
  std::vector<ContactModelDef> contact_models;
  Particles<Dim> particles;
  Walls<Dim> walls;
  PeriodicDefT<Dim> periodic_def;
  Periodic<Dim> periodic;
  ContactTable<Dim> contacts;
  ContactParamTable params;
  ShapeKind shape = ShapeKind::kRound;
  ContactLaw pair_law = ContactLaw::kLinear;  // the law of every particle-particle contact
  ContactLaw wall_law = ContactLaw::kLinear;  // the law of every particle-wall contact
  DampingDef damping;
  Vec<Dim> gravity = Vec<Dim>::Zero();
  PlanarParticle planar_particle = PlanarParticle::kDisc;
  double depth = 1.0;  // out-of-plane depth that turns 2D wall forces into stresses (3D: unused)
  double time_step = 0.0;
  double critical_time_step = 0.0;
  double time_step_fraction = 0.1;  // the user's settings the step came from
  double fixed_time_step = 0.0;
  double contact_tolerance = 0.0;   // BALL's TOL
  int threads = 1;
  std::uint64_t cycle = 0;
  double time = 0.0;
  // Neighbour-list bookkeeping: positions at the last rebuild and how far
  // particles and walls have moved since.
  std::vector<Vec<Dim>> reference_positions;
  double particle_travel = 0.0;
  double wall_travel = 0.0;
  bool contacts_stale = true;
  StepProfile profile;
  // Accumulated energy terms (the held terms, kinetic and strain, are
  // measured when asked) and the last cycle's particle-wise step check.
  EnergyBudget energy;
  double tangential_work = 0.0;  // done on the tangential springs; friction = this - what they hold
  double time_step_ratio = 0.0;
};

// Rebuilds the contact table from the broad phase (keeping history).
template <int Dim>
void find_contacts(WorldState<Dim>& state);

// Critical time step 2 sqrt(m/k) over particles and the stiffnesses they can meet.
template <int Dim>
double estimate_critical_time_step(const WorldState<Dim>& state);

template <int Dim>
AssemblyMeasures measure_assembly(const WorldState<Dim>& state);
template <int Dim>
std::vector<ContactRecordT<Dim>> list_contacts(const WorldState<Dim>& state);
template <int Dim>
std::optional<ContactRecordT<Dim>> find_pair_contact(const WorldState<Dim>& state, ParticleId a, ParticleId b);

template <int Dim>
WorldSnapshotT<Dim> save_snapshot(const WorldState<Dim>& state);
// Overwrites a freshly built state (from the snapshot's def) with the saved dynamic state.
template <int Dim>
void restore_snapshot(WorldState<Dim>& state, const WorldSnapshotT<Dim>& snapshot);

template <int Dim>
std::uint64_t hash_state(const WorldState<Dim>& state);

}  // namespace dem
