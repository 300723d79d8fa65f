// The force-displacement pass over the contact table: every contact computes
// its own force independently (in parallel); nothing is summed here. The
// contact law is chosen once per pass, for all particle-particle contacts
// and for all particle-wall contacts.
#pragma once

#include "contact_params.h"
#include "contact_table.h"
#include "particles.h"
#include "periodic.h"
#include "walls.h"

namespace dem {

// Energy flows of the contacts settled in one pass: the work the dashpots
// took out, the work done on the tangential springs (what they do not give
// back was lost to sliding and micro-slip), and the work of moving walls.
struct ContactEnergy {
  double damping = 0.0;
  double tangential_work = 0.0;
  double wall_work = 0.0;
  ContactEnergy& operator+=(const ContactEnergy& o) {
    damping += o.damping;
    tangential_work += o.tangential_work;
    wall_work += o.wall_work;
    return *this;
  }
};

template <int Dim>
ContactEnergy compute_pair_forces(ContactLaw law, ShapeKind shape, std::uint64_t cycle,
                                  const Particles<Dim>& particles, const Periodic<Dim>& periodic,
                                  std::vector<PairContact<Dim>>& pairs, std::vector<ContactForce<Dim>>& forces,
                                  const ContactParamTable& params, double dt, int threads);

template <int Dim>
ContactEnergy compute_wall_forces(ContactLaw law, ShapeKind shape, std::uint64_t cycle,
                                  const Particles<Dim>& particles, const Walls<Dim>& walls,
                         std::vector<WallContact<Dim>>& contacts, std::vector<ContactForce<Dim>>& forces,
                         const ContactParamTable& params, double dt, int threads);

}  // namespace dem
