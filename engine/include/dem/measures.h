// What a World reports: per-wall resultants (Cundall & Strack Table 1),
// assembly measures, and a view of each contact.
#pragma once

#include <cstdint>

#include "dem/ids.h"
#include "dem/math.h"

namespace dem {

// The resultant the particles exert on one wall.
struct WallMeasure {
  WallId wall = kInvalidId;
  Vec2 force = Vec2::Zero();   // N (per unit depth in 2D): sum of contact forces on the wall
  double moment = 0.0;         // N m, about the wall's reference point P, counter-clockwise
  double normal_force = 0.0;   // N, compressive component along the wall's normal
  int contacts = 0;            // number of touching particles
  // Eccentricity of the normal force divided by half the wall length,
  // e / (L/2) (Cundall & Strack Table 1, note 1); 0 without contacts.
  double eccentricity = 0.0;
  Vec2 point = Vec2::Zero();  // current position of P, m
  Vec2 displacement = Vec2::Zero();  // P's displacement since the world was built, m
};

struct AssemblyMeasures {
  double kinetic_energy = 0.0;  // J (per unit depth): translation + rotation
  // Largest resultant force on any particle over the largest contact force,
  // Delta F / F (Cundall & Strack Table 1, note 2); 0 without contacts.
  double out_of_balance = 0.0;
  double max_contact_force = 0.0;  // N
  int contacts = 0;                // touching particle-particle and particle-wall pairs
  int sliding_contacts = 0;        // those at the Coulomb limit (eq. 19)
};

// One touching contact. For a particle-wall contact, second_wall is set and
// second_particle is kInvalidId. The normal points from the first particle
// towards the second body (Cundall & Strack's e_i); forces follow the sign
// convention of Fig. 3 (positive normal force is compressive).
struct ContactRecord {
  ParticleId first = kInvalidId;
  ParticleId second_particle = kInvalidId;
  WallId second_wall = kInvalidId;
  Vec2 point = Vec2::Zero();   // m, halfway through the overlap
  Vec2 normal = Vec2::Zero();  // e_i, unit
  double overlap = 0.0;        // m
  double normal_force = 0.0;   // F_n, N (spring part)
  double shear_force = 0.0;    // F_s, N (spring part)
  double normal_damping = 0.0; // D_n, N (eq. 26)
  double shear_damping = 0.0;  // D_s, N (eq. 27)
  bool sliding = false;        // |F_s| reached (F_s)max
};

}  // namespace dem
