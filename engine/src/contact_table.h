// The contact table: every pair closer than the tolerance (BALL's TOL), with
// its history (the accumulated normal and shear forces of eq. 18) kept from
// cycle to cycle while the pair stays close, and a per-particle index so the
// force sums gather in a fixed order (bit-identical for any thread count).
#pragma once

#include <cstdint>
#include <vector>

#include "dem/ids.h"
#include "dem/math.h"

namespace dem {

// State shared by particle-particle and particle-wall contacts.
struct ContactState {
  // history, carried across cycles (eq. 18)
  double normal_force = 0.0;  // F_n, compressive positive
  double shear_force = 0.0;   // F_s
  bool touching = false;
  // results of the last force pass
  bool sliding = false;
  double overlap = 0.0;
  double normal_damping = 0.0;  // D_n (eq. 26)
  double shear_damping = 0.0;   // D_s (eq. 27)
  Vec2 normal = Vec2::Zero();   // e_i, from the particle towards the other body
  Vec2 point = Vec2::Zero();    // halfway through the overlap
};

// What a contact exerts this cycle (springs + dashpots), zero when it does
// not touch. Kept apart from the history rows: the force sums read only
// these 32 bytes per contact, which keeps the gathers in cache.
struct ContactForce {
  Vec2 force = Vec2::Zero();   // on the first particle; the second gets -force
  double moment_first = 0.0;   // on the first particle
  double moment_second = 0.0;  // on the second particle (pairs only)
};

struct PairContact {
  ParticleId first;   // first < second
  ParticleId second;
  ContactState state;
};

struct WallContact {
  ParticleId particle;
  WallId wall;
  ContactState state;
};

// A particle's view of its contacts: CSR offsets into an entry list.
// Pair entries encode 2 * contact + side (side 0 = first, 1 = second).
struct ContactIndex {
  std::vector<std::int32_t> pair_offsets;
  std::vector<std::int32_t> pair_entries;
  std::vector<std::int32_t> wall_offsets;
  std::vector<std::int32_t> wall_entries;
};

struct ContactTable {
  std::vector<PairContact> pairs;  // sorted by (first, second)
  std::vector<WallContact> walls;  // sorted by (particle, wall)
  std::vector<ContactForce> pair_forces;  // parallel to pairs
  std::vector<ContactForce> wall_forces;  // parallel to walls
  ContactIndex index;
};

struct Candidate {
  ParticleId first;
  std::int32_t second;  // a particle (pairs) or a wall
};

// Replaces the table's entries with the new candidate lists (both sorted),
// carrying over the history of every pair present in both.
void rebuild_contacts(ContactTable& table, const std::vector<Candidate>& pair_candidates,
                      const std::vector<Candidate>& wall_candidates, int particle_count);

}  // namespace dem
