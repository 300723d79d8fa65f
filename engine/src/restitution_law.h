// Linear spring-dashpot with a coefficient of restitution (Miyata et al.
// 2002, eqs. 13-23): F_n = k_n delta + c_n delta_dot with c_n from e
// (eq. 17), and an incremental shear spring with a Coulomb slider on the
// elastic normal force (eqs. 19-22).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "contact_history.h"
#include "contact_params.h"
#include "critical_step.h"
#include "linear_law.h"
#include "tangential.h"
#include "world_validation.h"

namespace dem {

struct RestitutionLaw {
  static constexpr ContactLaw kLaw = ContactLaw::kLinearRestitution;
  static constexpr const char* kName = "linear_restitution";
  static constexpr bool kNormalHistory = false;  // F_n = k_n delta (eq. 13)
  static constexpr bool kMindlin = false;
  static constexpr bool kHertz = false;
  static constexpr bool kBatchable = true;  // branch-free enough for contact_batch.h

  static void resolve(ContactParams& p, const ContactModelDef& model) {
    if (model.restitution < 1.0) {
      // Miyata eq. 17: c_n = 2 ln(1/e) sqrt(k_n m* / (pi^2 + ln^2(1/e))).
      const double log_inverse = std::log(1.0 / model.restitution);
      p.restitution_viscosity =
          2.0 * log_inverse *
          std::sqrt(p.normal_stiffness / (std::numbers::pi * std::numbers::pi + log_inverse * log_inverse));
    }
  }
  static void check_model(const ContactModelDef& model, const std::string& where) {
    check_linear_springs(model, where);
    check(model.restitution > 0.0 && model.restitution <= 1.0, where + ": restitution must be in (0, 1]");
  }
  // Miyata eq. 17's dashpot with the mass against a wall (m* = m), no shear dashpot.
  static double critical_time_step(const StepParticle& particle, const ContactParams& c, const DampingDef& damping) {
    return linear_critical_step(particle, c, c.restitution_viscosity * std::sqrt(particle.mass), 0.0, damping);
  }
  static double undamped_critical_time_step(const StepParticle& particle, const ContactParams& c) {
    return linear_undamped_critical_step(particle, c);
  }

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
