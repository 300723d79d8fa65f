// Force sums per particle and the law of motion (Cundall & Strack eqs.
// 20-23a, with global damping eqs. 29-36 and the body force term).
#pragma once

#include "contact_table.h"
#include "particles.h"
#include "walls.h"

namespace dem {

// Gathers each particle's contact forces and moments in the fixed order of
// the contact index: no racing sums, the same bits for any thread count.
template <int Dim>
void sum_particle_forces(Particles<Dim>& particles, const ContactTable<Dim>& table, int threads);

// Gathers the force each wall receives and the eccentricity sums, in contact order.
template <int Dim>
void sum_wall_forces(Walls<Dim>& walls, const std::vector<WallContact<Dim>>& contacts,
                     const std::vector<ContactForce<Dim>>& forces);

// Time-centred central differences (eqs. 35-36, then 22a-23a); returns the
// largest distance of any particle from its position in `reference` (where
// the contact table was last rebuilt), for the neighbour-list check.
template <int Dim>
double integrate_motion(Particles<Dim>& particles, const std::vector<Vec<Dim>>& reference, const Vec<Dim>& gravity,
                        double global_alpha, double dt, int threads);

}  // namespace dem
