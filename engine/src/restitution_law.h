// Linear spring-dashpot with a coefficient of restitution (Miyata et al.
// 2002, eqs. 13-23): F_n = k_n delta + c_n delta_dot with c_n from e
// (eq. 17), and an incremental shear spring with a Coulomb slider on the
// elastic normal force (eqs. 19-22).
#pragma once

#include <algorithm>
#include <cmath>

#include "contact_kinematics.h"
#include "contact_params.h"
#include "contact_table.h"
#include "tangential.h"

namespace dem {

struct RestitutionLaw {
  template <int Dim>
  static void apply(ContactState<Dim>& s, const ContactKinematics<Dim>& k, const PairProperties& pair,
                      const ContactParams& p, double dt) {
    if (!s.touching) {
      s.shear = zero_shear<Dim>();  // eq. 19: the shear force starts at zero
      s.touching = true;
    } else {
      s.shear += p.shear_stiffness * k.shear_velocity * dt;  // eqs. 19-21
    }
    s.overlap = k.overlap;
    s.normal_force = p.normal_stiffness * k.overlap;  // eq. 13
    // eq. 17 with the pair's effective mass (eq. 18).
    s.normal_damping = p.restitution_viscosity * std::sqrt(pair.effective_mass) * k.normal_velocity;  // eq. 14
    const double shear_limit = std::max(0.0, p.friction * s.normal_force + p.cohesion);  // eq. 22
    apply_coulomb_limit(s, shear_limit);
    s.shear_damping = zero_shear<Dim>();
  }
};

}  // namespace dem
