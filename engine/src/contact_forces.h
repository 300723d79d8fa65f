// The force-displacement pass over the contact table: every contact computes
// its own force independently (in parallel); nothing is summed here. The
// contact law is chosen once per pass, for all particle-particle contacts
// and for all particle-wall contacts.
#pragma once

#include "contact_params.h"
#include "contact_table.h"
#include "particles.h"
#include "walls.h"

namespace dem {

template <int Dim>
void compute_pair_forces(ContactLaw law, const Particles<Dim>& particles, std::vector<PairContact<Dim>>& pairs,
                         std::vector<ContactForce<Dim>>& forces, const ContactParamTable& params, double dt,
                         int threads);

template <int Dim>
void compute_wall_forces(ContactLaw law, const Particles<Dim>& particles, const Walls<Dim>& walls,
                         std::vector<WallContact<Dim>>& contacts, std::vector<ContactForce<Dim>>& forces,
                         const ContactParamTable& params, double dt, int threads);

}  // namespace dem
