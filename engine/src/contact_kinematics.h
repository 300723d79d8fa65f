// What every contact law is told about one contact in one cycle.
#pragma once

#include "dem/snapshot.h"

namespace dem {

template <int Dim>
struct ContactKinematics {
  double overlap;                  // R_x + R_y - D (Cundall & Strack eq. 8), > 0
  double normal_velocity;          // n_dot (eq. 12), compression positive
  ShearForce<Dim> shear_velocity;  // s_dot (eq. 13); a tangent-plane vector in 3D
  Vec<Dim> normal;                 // e_i
};

// Effective radius and mass of the pair (Randall 4.5-4.6); a wall counts
// as infinitely large and heavy, so a particle-wall pair takes the particle's.
struct PairProperties {
  double effective_radius;
  double effective_mass;
};

}  // namespace dem
