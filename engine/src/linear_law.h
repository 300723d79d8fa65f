// BALL's force-displacement law at one contact (Cundall & Strack 1979,
// eqs. 16-19, with contact damping eqs. 26-28).
#pragma once

#include <cmath>

#include "contact_params.h"
#include "contact_table.h"

namespace dem {

// What the force law needs to know of the contact's motion this cycle.
struct ContactKinematics {
  double overlap;          // R_x + R_y - D (eq. 8), > 0
  double normal_velocity;  // n_dot (eq. 12), compression positive
  double shear_velocity;   // s_dot (eq. 13)
};

// Updates the contact's force history and dashpot forces for one cycle.
inline void apply_linear_law(ContactState& s, const ContactKinematics& k, const ContactParams& p, double dt) {
  if (!s.touching) {
    // A contact that forms during the step starts from its overlap (the
    // integral of eq. 16 since touching) and no shear history.
    s.normal_force = p.normal_stiffness * k.overlap;
    s.shear_force = 0.0;
    s.touching = true;
  } else {
    s.normal_force += p.normal_stiffness * k.normal_velocity * dt;  // eqs. 16, 18
    s.shear_force += p.shear_stiffness * k.shear_velocity * dt;     // eqs. 17, 18
  }
  s.overlap = k.overlap;
  // Coulomb limit with cohesion (eq. 19); never negative, even under tension.
  const double shear_limit = std::max(0.0, s.normal_force * p.friction + p.cohesion);
  s.sliding = std::abs(s.shear_force) > shear_limit;
  if (s.sliding) s.shear_force = std::copysign(shear_limit, s.shear_force);
  // Dashpots (eqs. 26-28); no shear dashpot while sliding: friction alone damps.
  s.normal_damping = p.normal_viscosity * k.normal_velocity;
  s.shear_damping = s.sliding ? 0.0 : p.shear_viscosity * k.shear_velocity;
}

// A pair that no longer overlaps carries no force and loses its history.
inline void separate(ContactState& s) {
  s = ContactState{};
}

}  // namespace dem
