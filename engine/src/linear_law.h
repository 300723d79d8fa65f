// BALL's force-displacement law at one contact (Cundall & Strack 1979,
// eqs. 16-19, with contact damping eqs. 26-28), in either dimension.
#pragma once

#include <algorithm>

#include "contact_history.h"
#include "contact_params.h"
#include "tangential.h"

namespace dem {

struct LinearLaw {
  static constexpr bool kNormalHistory = true;  // F_n is accumulated (eq. 18)
  static constexpr bool kMindlin = false;
  static constexpr bool kBatchable = true;  // branch-free enough for contact_batch.h

  template <int Dim>
  [[gnu::always_inline]] static void advance(ContactHistory<Dim>& h, const ContactKinematics<Dim>& k,
                                             const PairProperties&, const ContactParams& p, double dt) {
    // A contact that forms during the step starts from its overlap (the
    // integral of eq. 16 since touching) and no shear history.
    h.normal_force = choose(h.touching, h.normal_force + p.normal_stiffness * k.normal_velocity * dt,  // eqs. 16, 18
                            p.normal_stiffness * k.overlap);
    h.shear = choose(h.touching, ShearForce<Dim>(h.shear + p.shear_stiffness * k.shear_velocity * dt),  // eqs. 17, 18
                     zero_shear<Dim>());
    h.touching = true;
    // Coulomb limit with cohesion (eq. 19); never negative, even under tension.
    apply_coulomb_limit(h, std::max(0.0, h.normal_force * p.friction + p.cohesion));
  }

  template <int Dim>
  [[gnu::always_inline]] static ContactForces<Dim> forces(const ContactHistory<Dim>& h, const ContactKinematics<Dim>& k,
                                                          const PairProperties&, const ContactParams& p) {
    // Dashpots (eqs. 26-28); no shear dashpot while sliding: friction alone damps.
    return {h.normal_force, p.normal_viscosity * k.normal_velocity, h.shear,
            choose(h.sliding, zero_shear<Dim>(), ShearForce<Dim>(p.shear_viscosity * k.shear_velocity))};
  }
};

}  // namespace dem
