// Broad phase: a uniform cell grid finds every pair whose gap is below the
// contact tolerance, in time linear in the number of particles.
#pragma once

#include <vector>

#include "contact_table.h"
#include "particles.h"
#include "periodic.h"
#include "walls.h"

namespace dem {

// Sorted (first < second) particle pairs with gap < tolerance, across
// periodic boundaries through the nearest image.
template <int Dim>
std::vector<Candidate> find_pair_candidates(const Particles<Dim>& particles, const Periodic<Dim>& periodic,
                                            double tolerance, int threads);

// Sorted (particle, wall) pairs whose gap to the wall is < tolerance.
template <int Dim>
std::vector<Candidate> find_wall_candidates(const Particles<Dim>& particles, const Walls<Dim>& walls,
                                            double tolerance);

}  // namespace dem
