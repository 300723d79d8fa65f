// Broad phase: a uniform cell grid finds every pair whose gap is below the
// contact tolerance, in time linear in the number of particles. The keys
// come out in the contact table's order.
#pragma once

#include <vector>

#include "contact_table.h"
#include "particles.h"
#include "periodic.h"
#include "walls.h"

namespace dem {

// Particle pairs with gap < tolerance, across periodic boundaries through
// the nearest image, as pair-row keys (first: the lower id's slot), sorted.
template <int Dim>
std::vector<ContactKey> find_pair_keys(const Particles<Dim>& particles, const Periodic<Dim>& periodic, double tolerance,
                                       int threads);

// (particle slot, wall) pairs whose gap to the wall is < tolerance, sorted.
template <int Dim>
std::vector<ContactKey> find_wall_keys(const Particles<Dim>& particles, const Walls<Dim>& walls, double tolerance);

}  // namespace dem
