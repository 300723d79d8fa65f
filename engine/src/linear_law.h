// BALL's force-displacement law at one contact (Cundall & Strack 1979,
// eqs. 16-19, with contact damping eqs. 26-28), in either dimension.
#pragma once

#include <algorithm>
#include <cmath>

#include "contact_kinematics.h"
#include "contact_params.h"
#include "contact_table.h"
#include "tangential.h"

namespace dem {

struct LinearLaw {
  template <int Dim>
  static void apply(ContactState<Dim>& s, const ContactKinematics<Dim>& k, const PairProperties&,
                      const ContactParams& p, double dt) {
    if (!s.touching) {
      // A contact that forms during the step starts from its overlap (the
      // integral of eq. 16 since touching) and no shear history.
      s.normal_force = p.normal_stiffness * k.overlap;
      s.shear = zero_shear<Dim>();
      s.touching = true;
    } else {
      s.normal_force += p.normal_stiffness * k.normal_velocity * dt;  // eqs. 16, 18
      s.shear += p.shear_stiffness * k.shear_velocity * dt;           // eqs. 17, 18
    }
    s.overlap = k.overlap;
    // Coulomb limit with cohesion (eq. 19); never negative, even under tension.
    const double shear_limit = std::max(0.0, s.normal_force * p.friction + p.cohesion);
    apply_coulomb_limit(s, shear_limit);
    // Dashpots (eqs. 26-28); no shear dashpot while sliding: friction alone damps.
    s.normal_damping = p.normal_viscosity * k.normal_velocity;
    s.shear_damping = s.sliding ? zero_shear<Dim>() : ShearForce<Dim>(p.shear_viscosity * k.shear_velocity);
  }
};

// A pair that no longer overlaps carries no force and loses its history
// (a superquadric pair keeps where its contact search ended, to start there).
template <int Dim>
void separate(ContactState<Dim>& s) {
  ContactState<Dim> fresh;
  fresh.search_first = s.search_first;
  fresh.search_second = s.search_second;
  fresh.has_search = s.has_search;
  s = fresh;
}

}  // namespace dem
