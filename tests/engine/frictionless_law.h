// A contact law that lives only in the tests, to show what a new law is:
// this file and its entry in a list of laws (test_law_list.cpp). A
// frictionless linear spring with a normal dashpot, F_n = k_n delta +
// c_n delta_dot (Cundall & Strack eqs. 16 and 26 without the history of
// eq. 18), no tangential force: a smooth contact (Cundall & Strack's
// friction set to zero, without a shear spring).
#pragma once

#include <string>

#include "contact_history.h"
#include "contact_params.h"
#include "critical_step.h"
#include "world_validation.h"

namespace dem::testing {

struct FrictionlessLaw {
  // Its value of ContactLaw: the engine's enum lists no such law.
  static constexpr ContactLaw kLaw{41};
  static constexpr const char* kName = "frictionless";
  static constexpr bool kNormalHistory = false;
  static constexpr bool kMindlin = false;
  static constexpr bool kHertz = false;
  static constexpr bool kBatchable = true;

  // No shear spring and no friction: the pair's set says so, whatever the
  // materials' friction.
  static void resolve(ContactParams& p, const ContactModelDef&) {
    p.shear_stiffness = 0.0;
    p.shear_viscosity = 0.0;
    p.friction = 0.0;
  }
  static void check_model(const ContactModelDef& model, const std::string& where) {
    check(model.linear.normal_stiffness > 0.0, where + ": normal stiffness must be > 0");
  }
  // The normal mode alone, with its dashpot.
  static double critical_time_step(const StepParticle& particle, const ContactParams& c, const DampingDef& damping) {
    return mode_critical_step(particle.mass, c.normal_stiffness, c.normal_viscosity, damping.local_alpha);
  }
  static double undamped_critical_time_step(const StepParticle& particle, const ContactParams& c) {
    return mode_critical_step(particle.mass, c.normal_stiffness, 0.0, 0.0);
  }

  template <int Dim>
  static void advance(ContactHistory<Dim>& h, const ContactKinematics<Dim>&, const PairProperties&,
                      const ContactParams&, double) {
    h.touching = true;
  }
  template <int Dim>
  static ContactForces<Dim> forces(const ContactHistory<Dim>&, const ContactKinematics<Dim>& k, const PairProperties&,
                                   const ContactParams& p) {
    return {p.normal_stiffness * k.overlap, p.normal_viscosity * k.normal_velocity, zero_shear<Dim>(),
            zero_shear<Dim>()};
  }
};

}  // namespace dem::testing
