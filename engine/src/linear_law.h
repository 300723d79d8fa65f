// BALL's force-displacement law at one contact (Cundall & Strack 1979,
// eqs. 16-19, with contact damping eqs. 26-28), in either dimension.
#pragma once

#include <algorithm>
#include <string>

#include "contact_history.h"
#include "contact_params.h"
#include "critical_step.h"
#include "tangential.h"
#include "world_validation.h"

namespace dem {

// The linear springs' model: k_n > 0, k_s >= 0 (eqs. 16-17).
inline void check_linear_springs(const ContactModelDef& model, const std::string& where) {
  check(model.linear.normal_stiffness > 0.0, where + ": normal stiffness must be > 0");
  check(model.linear.shear_stiffness >= 0.0, where + ": shear stiffness must be >= 0");
}

struct LinearLaw {
  static constexpr ContactLaw kLaw = ContactLaw::kLinear;
  static constexpr const char* kName = "linear";
  static constexpr bool kNormalHistory = true;  // F_n is accumulated (eq. 18)
  static constexpr bool kMindlin = false;
  static constexpr bool kHertz = false;
  static constexpr bool kBatchable = true;  // branch-free enough for contact_batch.h

  // The springs and BALL's dashpots c = beta k (eq. 28) every pair resolves
  // (contact_params.cpp); nothing of its own.
  static void resolve(ContactParams&, const ContactModelDef&) {}
  static void check_model(const ContactModelDef& model, const std::string& where) {
    check_linear_springs(model, where);
  }
  // The modes of k_n, k_s and the rolling spring with the dashpots of eq. 28.
  static double critical_time_step(const StepParticle& particle, const ContactParams& c, const DampingDef& damping) {
    return linear_critical_step(particle, c, c.normal_viscosity, c.shear_viscosity, damping);
  }
  static double undamped_critical_time_step(const StepParticle& particle, const ContactParams& c) {
    return linear_undamped_critical_step(particle, c);
  }

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
