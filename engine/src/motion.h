// Force sums per particle and the law of motion (Cundall & Strack eqs.
// 20-23a, with global damping eqs. 29-36 and the body force term).
#pragma once

#include "contact_table.h"
#include "particles.h"
#include "walls.h"

namespace dem {

// Gathers each particle's contact forces and moments in the fixed order of
// the contact index: no racing sums, the same bits for any thread count.
void sum_particle_forces(Particles& particles, const ContactTable& table, int threads);

// Gathers the force each wall receives and the eccentricity sums, in contact order.
void sum_wall_forces(Walls& walls, const std::vector<WallContact>& contacts, const std::vector<ContactForce>& forces);

// Time-centred central differences (eqs. 35-36, then 22a-23a); returns the
// largest distance of any particle from its position in `reference` (where
// the contact table was last rebuilt), for the neighbour-list check.
double integrate_motion(Particles& particles, const std::vector<Vec2>& reference, const Vec2& gravity,
                        double global_alpha, double dt, int threads);

}  // namespace dem
