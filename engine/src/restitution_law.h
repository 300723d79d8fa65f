// Linear spring-dashpot with a coefficient of restitution (Miyata et al.
// 2002, eqs. 13-23): F_n = k_n delta + c_n delta_dot with c_n from e
// (eq. 17), and an incremental shear spring with a Coulomb slider on the
// elastic normal force (eqs. 19-22).
#pragma once

#include <algorithm>
#include <cmath>

#include "contact_history.h"
#include "contact_params.h"
#include "tangential.h"

namespace dem {

struct RestitutionLaw {
  static constexpr bool kNormalHistory = false;  // F_n = k_n delta (eq. 13)
  static constexpr bool kMindlin = false;
  static constexpr bool kBatchable = true;  // branch-free enough for contact_batch.h

  template <int Dim>
  [[gnu::always_inline]] static void advance(ContactHistory<Dim>& h, const ContactKinematics<Dim>& k,
                                             const PairProperties&, const ContactParams& p, double dt) {
    // eqs. 19-21; the shear force starts at zero (eq. 19).
    h.shear =
        choose(h.touching, ShearForce<Dim>(h.shear + p.shear_stiffness * k.shear_velocity * dt), zero_shear<Dim>());
    h.touching = true;
    apply_coulomb_limit(h, std::max(0.0, p.friction * (p.normal_stiffness * k.overlap) + p.cohesion));  // eq. 22
  }

  template <int Dim>
  [[gnu::always_inline]] static ContactForces<Dim> forces(const ContactHistory<Dim>& h, const ContactKinematics<Dim>& k,
                                                          const PairProperties& pair, const ContactParams& p) {
    // eq. 17 with the pair's effective mass (eq. 18).
    return {p.normal_stiffness * k.overlap,                                                // eq. 13
            p.restitution_viscosity * std::sqrt(pair.effective_mass) * k.normal_velocity,  // eq. 14
            h.shear, zero_shear<Dim>()};
  }
};

}  // namespace dem
