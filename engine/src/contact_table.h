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
  Vec2 force = Vec2::Zero();    // total force on the first particle (springs + dashpots)
  double moment_first = 0.0;    // moment on the first particle
};

struct PairContact {
  ParticleId first;   // first < second
  ParticleId second;
  ContactState state;
  double moment_second = 0.0;  // moment on the second particle
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
