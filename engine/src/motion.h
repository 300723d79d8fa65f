// Force sums per particle and the law of motion (Cundall & Strack eqs.
// 20-23a, with global damping eqs. 29-36 and the body force term).
#pragma once

#include "contact_table.h"
#include "particles.h"
#include "periodic.h"
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

// What one integration step reports.
struct MotionStep {
  double max_travel = 0.0;       // largest distance from the positions at the last contact-table rebuild
  double gravity_work = 0.0;     // J
  double global_damping = 0.0;   // J dissipated
  double local_damping = 0.0;    // J dissipated
  double time_step_ratio = 0.0;  // dt over the smallest particle-wise critical step (Randall 4.35-4.40)
};

// Time-centred central differences (Cundall & Strack eqs. 35-36, then
// 22a-23a) with the body force, global damping (eq. 34; Miyata eq. 32) and
// local non-viscous damping (Miyata eq. 33).
// Positions that leave a periodic cell enter it on the other side.
// Ellipsoids (`tensor_rotation`) turn by Euler's equations with their inertia tensor.
template <int Dim>
MotionStep integrate_motion(Particles<Dim>& particles, const std::vector<Vec<Dim>>& reference,
                            const Periodic<Dim>& periodic, const Vec<Dim>& gravity, const DampingDef& damping,
                            bool tensor_rotation, double dt, int threads);

}  // namespace dem
