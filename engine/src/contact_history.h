// What every contact law works on: one row's history as a value, the
// kinematics of the contact this cycle, and the forces the law answers with.
// A law has two parts: advance() moves the history over one step (the
// increments of eqs. 16-18, the Coulomb limit of eq. 19, Mindlin's loading
// history), forces() turns the history as it stands into the springs' and
// dashpots' forces. The force pass calls both; a contact report calls only
// forces(), on the same history and kinematics, and so shows exactly what
// the pass applied.
#pragma once

#include "contact_table.h"
#include "dem/snapshot.h"

namespace dem {

template <int Dim>
struct ContactHistory {
  ShearForce<Dim> shear = zero_shear<Dim>();  // F_s
  double normal_force = 0.0;                  // F_n, for laws that keep it (kNormalHistory)
  bool touching = false;
  bool sliding = false;
  MindlinRow<Dim> mindlin;  // Hertz-Mindlin only (kMindlin)
};

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

// The forces of one contact, compressive normal positive (Cundall & Strack Fig. 3).
template <int Dim>
struct ContactForces {
  double normal = 0.0;                                // F_n, the spring
  double normal_damping = 0.0;                        // D_n (eq. 26)
  ShearForce<Dim> shear = zero_shear<Dim>();          // F_s, the spring
  ShearForce<Dim> shear_damping = zero_shear<Dim>();  // D_s (eq. 27)
};

// Loads the columns law `Law` uses from row r.
template <typename Law, int Dim>
ContactHistory<Dim> load_history(const ContactRows<Dim>& rows, std::size_t r) {
  ContactHistory<Dim> h;
  h.shear = rows.shear[r];
  h.touching = rows.touching(r);
  h.sliding = rows.sliding(r);
  if constexpr (Law::kNormalHistory) h.normal_force = rows.normal_force[r];
  if constexpr (Law::kMindlin) h.mindlin = rows.mindlin[r];
  return h;
}

template <typename Law, int Dim>
void store_history(ContactRows<Dim>& rows, std::size_t r, const ContactHistory<Dim>& h) {
  rows.shear[r] = h.shear;
  rows.flags[r] = static_cast<std::uint8_t>((h.touching ? kTouching : 0) | (h.sliding ? kSliding : 0));
  if constexpr (Law::kNormalHistory) rows.normal_force[r] = h.normal_force;
  if constexpr (Law::kMindlin) rows.mindlin[r] = h.mindlin;
}

}  // namespace dem
