// The contact table: every pair closer than the tolerance (BALL's TOL), with
// its history (the accumulated normal and shear forces of eq. 18) kept from
// cycle to cycle while the pair stays close, and a per-particle index so the
// force sums gather in a fixed order (bit-identical for any thread count).
#pragma once

#include <cstdint>
#include <vector>

#include "dem/ids.h"
#include "dem/snapshot.h"
#include "mindlin.h"

namespace dem {

// State shared by particle-particle and particle-wall contacts.
template <int Dim>
struct ContactState {
  // history, carried across cycles (eq. 18)
  double normal_force = 0.0;    // F_n, compressive positive
  ShearForce<Dim> shear = zero_shear<Dim>();  // F_s: signed along t_i (2D) or a tangent-plane vector (3D)
  bool touching = false;
  // results of the last force pass
  bool sliding = false;
  double overlap = 0.0;
  double normal_damping = 0.0;        // D_n (eq. 26)
  ShearForce<Dim> shear_damping = zero_shear<Dim>();  // D_s (eq. 27)
  Vec<Dim> normal = Vec<Dim>::Zero();  // e_i, from the particle towards the other body
  Vec<Dim> point = Vec<Dim>::Zero();   // halfway through the overlap
  // Mindlin-Deresiewicz history (Hertz-Mindlin law only); in 3D the law
  // works along a loading axis in the tangent plane.
  MindlinHistory mindlin;
  Vec<Dim> mindlin_axis = Vec<Dim>::Zero();
  // Energy bookkeeping: the dashpot force applied last cycle (on the first
  // body) and the relative velocity it was computed from. Its work is only
  // known once the next relative velocity is: it acts over the step the
  // central differences centre on (see contact_forces.cpp).
  Vec<Dim> dashpot_force = Vec<Dim>::Zero();
  Vec<Dim> relative_velocity = Vec<Dim>::Zero();
  // Superquadrics and ellipsoids: where last cycle's two contact searches
  // ended (parametric angles, Miyata 2.3; Lagrange multipliers, 2.4), to
  // start this cycle's near them.
  double search_first = 0.0, search_second = 0.0;
  bool has_search = false;
  std::uint64_t formed_cycle = 0;  // the cycle the contact began touching
};

// What a contact exerts this cycle (springs + dashpots), zero when it does
// not touch. Kept apart from the history rows: the force sums read only
// these few bytes per contact, which keeps the gathers in cache.
template <int Dim>
struct ContactForce {
  Vec<Dim> force = Vec<Dim>::Zero();  // on the first particle; the second gets -force
  Spin<Dim> moment_first = Space<Dim>::zero_spin();
  Spin<Dim> moment_second = Space<Dim>::zero_spin();  // pairs only
};

template <int Dim>
struct PairContact {
  ParticleId first;   // first < second
  ParticleId second;
  ContactState<Dim> state;
};

template <int Dim>
struct WallContact {
  ParticleId particle;
  WallId wall;
  ContactState<Dim> state;
};

// A particle's view of its contacts: CSR offsets into an entry list.
// Pair entries encode 2 * contact + side (side 0 = first, 1 = second).
struct ContactIndex {
  std::vector<std::int32_t> pair_offsets;
  std::vector<std::int32_t> pair_entries;
  std::vector<std::int32_t> wall_offsets;
  std::vector<std::int32_t> wall_entries;
};

template <int Dim>
struct ContactTable {
  std::vector<PairContact<Dim>> pairs;  // sorted by (first, second)
  std::vector<WallContact<Dim>> walls;  // sorted by (particle, wall)
  std::vector<ContactForce<Dim>> pair_forces;  // parallel to pairs
  std::vector<ContactForce<Dim>> wall_forces;  // parallel to walls
  ContactIndex index;
};

struct Candidate {
  ParticleId first;
  std::int32_t second;  // a particle (pairs) or a wall
};

// Rebuilds the per-particle index after rows were dropped or renumbered.
template <int Dim>
void reindex_contacts(ContactTable<Dim>& table, int particle_count);

// Replaces the table's entries with the new candidate lists (both sorted),
// carrying over the history of every pair present in both.
template <int Dim>
void rebuild_contacts(ContactTable<Dim>& table, const std::vector<Candidate>& pair_candidates,
                      const std::vector<Candidate>& wall_candidates, int particle_count);

}  // namespace dem
