// The force-displacement pass over the contact table: every contact computes
// its own force independently (in parallel); nothing is summed here.
#pragma once

#include "contact_params.h"
#include "contact_table.h"
#include "particles.h"
#include "walls.h"

namespace dem {

void compute_pair_forces(const Particles& particles, std::vector<PairContact>& pairs,
                         std::vector<ContactForce>& forces, const ContactParamTable& params, double dt,
                         int threads);

void compute_wall_forces(const Particles& particles, const Walls& walls, std::vector<WallContact>& contacts,
                         std::vector<ContactForce>& forces, const ContactParamTable& params, double dt,
                         int threads);

}  // namespace dem
