// Hertz normal force with two tangential laws: Mindlin-Deresiewicz with its
// loading history (Randall 1989) and the linear-pressure-dependent
// stiffness 8 G* a (Miyata et al. 2002, eq. 31).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "contact_history.h"
#include "contact_params.h"
#include "critical_step.h"
#include "mindlin.h"
#include "tangential.h"
#include "world_validation.h"

namespace dem {

// The normal part both Hertz laws share. Randall codes Hertz incrementally
// (4.11-4.12), which drifts from the curve it integrates; we use the curve
// itself, N = 4/3 E* (R* alpha^3)^(1/2) = 4/3 E* a alpha with a = (R* alpha)^(1/2)
// (Randall 3.12-3.13; Miyata eq. 24).
struct HertzContact {
  double contact_radius;  // a (3.12)
  double normal_force;    // N (3.13)
};

DEM_INLINE HertzContact hertz_contact(double overlap, const PairProperties& pair, const ContactParams& p) {
  const double a = std::sqrt(pair.effective_radius * overlap);
  return {a, 4.0 / 3.0 * p.contact_modulus * a * overlap};
}

// Dashpots at a fraction beta of the critical damping of the normal
// stiffness dN/d(alpha) = 2 E* a (Randall 3.15, 4.13) and of a tangential
// stiffness 8 G* a theta (Randall 4.19; theta = 1 for the linear-pressure
// law), the latter off unless asked for: 2 beta sqrt(m* k) times the
// velocity, from one root sqrt(m* a) (ContactParams::normal_dashpot).
// No tangential dashpot while sliding: friction alone damps.
template <int Dim>
DEM_INLINE ContactForces<Dim> hertz_forces(const ContactHistory<Dim>& h, const ContactKinematics<Dim>& k,
                                           const PairProperties& pair, const ContactParams& p, const HertzContact& c,
                                           double root_theta) {
  const double root = std::sqrt(pair.effective_mass * c.contact_radius);
  ContactForces<Dim> f;
  f.normal = c.normal_force;
  f.normal_damping = p.normal_dashpot * root * k.normal_velocity;
  f.shear = h.shear;
  f.shear_damping = choose(h.sliding, zero_shear<Dim>(),
                           ShearForce<Dim>(p.tangential_dashpot * root_theta * root * k.shear_velocity));
  return f;
}

// What both Hertz laws share besides the normal force: their dashpots'
// resolution and checks, and their time step.
struct HertzLawBase {
  static constexpr bool kHertz = true;

  // The damping ratio beta (Randall 4.13), from a coefficient of restitution
  // when one is given, and the dashpots' coefficients over sqrt(m* a)
  // (ContactParams::normal_dashpot) from E* and G* of the pair.
  static void resolve(ContactParams& p, const ContactModelDef& model) {
    p.damping_ratio =
        model.hertz.restitution ? damping_ratio_from_restitution(*model.hertz.restitution) : model.hertz.damping_ratio;
    p.tangential_damping_ratio = model.hertz.tangential ? p.damping_ratio : 0.0;
    p.normal_dashpot = 2.0 * p.damping_ratio * std::sqrt(2.0 * p.contact_modulus);
    p.tangential_dashpot = 2.0 * p.tangential_damping_ratio * std::sqrt(8.0 * p.shear_modulus);
  }
  static void check_model(const ContactModelDef& model, const std::string& where) {
    check(model.hertz.damping_ratio >= 0.0, where + ": damping ratio must be >= 0");
    check(!model.hertz.restitution || (*model.hertz.restitution > 0.0 && *model.hertz.restitution <= 1.0),
          where + ": restitution must be in (0, 1]");
  }
  // The Rayleigh step of the particle (Randall 4.33), as it is, damped or
  // not: Randall takes it as the step itself, with dashpots at 10-20 % of
  // critical (his hopper and pluvial runs). It is a wave's crossing time,
  // not a contact's limit: a Hertz contact stiffens with its overlap
  // (k_n = 2 E* a), and at the overlaps of such runs its own limit lies
  // above the Rayleigh step - which a dashpot shortens, and a step set from
  // the Rayleigh step does not follow.
  static double critical_time_step(const StepParticle& particle, const ContactParams&, const DampingDef&) {
    return rayleigh_time_step(particle.material, particle.radius);
  }
  static double undamped_critical_time_step(const StepParticle& particle, const ContactParams&) {
    return rayleigh_time_step(particle.material, particle.radius);
  }
};

struct HertzMindlinLaw : HertzLawBase {
  static constexpr ContactLaw kLaw = ContactLaw::kHertzMindlin;
  static constexpr const char* kName = "hertz_mindlin";
  static constexpr bool kNormalHistory = true;  // dN over the step
  static constexpr bool kMindlin = true;
  static constexpr bool kBatchable = false;  // the loading history branches per contact

  template <int Dim>
  [[gnu::always_inline]] static void advance(ContactHistory<Dim>& h, const ContactKinematics<Dim>& k,
                                             const PairProperties& pair, const ContactParams& p, double dt) {
    // A fresh contact: its normal force and contact area are set before the
    // tangential increment (Randall 3.4: "update the normal force and contact
    // area radius followed by calculating dT using the new values"), so the
    // step that forms it is tangential loading at its new N, with dN = 0.
    // Counting the whole N as dN would book a lag DD (4.16-4.17) of about
    // mu N / (8 G* a): the displacement from an area that carried traction
    // up to the curve of the larger N (Fig. 3.9, A to B). A contact that
    // forms carries no traction: its state (T = 0, delta = 0) lies on the
    // virgin curve of any N, so it lags behind nothing, and a later slowly
    // rising N must find it on Mindlin's curve, not at theta = 1 up to mu N.
    const bool formed = h.touching;
    if (!formed) {
      h.shear = zero_shear<Dim>();
      h.normal_force = 0.0;
      h.mindlin = MindlinRow<Dim>{};
    }
    const HertzContact c = hertz_contact(k.overlap, pair, p);
    const double force_change = formed ? c.normal_force - h.normal_force : 0.0;
    h.normal_force = c.normal_force;
    h.touching = true;
    const ShearForce<Dim> ds = k.shear_velocity * dt;
    const double mu = p.friction;
    double theta;
    if constexpr (Dim == 2) {
      // F_s along t_i is the law's signed T.
      theta = mindlin_step(h.mindlin.history, h.shear, h.normal_force, force_change, c.contact_radius, ds, mu,
                           p.shear_modulus);
    } else {
      // In 3D the law runs along a loading axis in the tangent plane, set
      // by the first tangential displacement and turned with the contact;
      // displacement across the axis meets the current stiffness 8 G* a theta.
      Vec3& axis = h.mindlin.axis;
      axis -= axis.dot(k.normal) * k.normal;
      if (axis.squaredNorm() < 1e-24) {
        axis = ds.norm() > 0.0 ? Vec3(ds.normalized()) : Vec3::Zero();
      } else {
        axis.normalize();
      }
      double along = h.shear.dot(axis);
      const Vec3 across = h.shear - along * axis;
      const double ds_along = ds.dot(axis);
      theta = mindlin_step(h.mindlin.history, along, h.normal_force, force_change, c.contact_radius, ds_along, mu,
                           p.shear_modulus);
      h.shear = along * axis + across + 8.0 * p.shear_modulus * c.contact_radius * theta * (ds - ds_along * axis);
    }
    h.mindlin.theta = theta;
    const double limit = std::max(0.0, mu * h.normal_force + p.cohesion);
    // With theta = 0 the law lands exactly on mu N: full slip (Randall 3.95), so
    // reaching the limit counts as sliding, not only passing it.
    const double magnitude = shear_magnitude(h.shear);
    h.sliding = magnitude > limit || (limit > 0.0 && magnitude >= limit * (1.0 - 1e-12));
    if (h.sliding) {
      clamp_shear(h.shear, limit);
      if constexpr (Dim == 2) {
        mindlin_slide(h.mindlin.history, h.shear);
      } else {
        if (limit > 0.0) h.mindlin.axis = h.shear.normalized();
        mindlin_slide(h.mindlin.history, limit);
      }
    }
  }

  template <int Dim>
  [[gnu::always_inline]] static ContactForces<Dim> forces(const ContactHistory<Dim>& h, const ContactKinematics<Dim>& k,
                                                          const PairProperties& pair, const ContactParams& p) {
    const HertzContact c = hertz_contact(k.overlap, pair, p);
    return hertz_forces(h, k, pair, p, c, std::sqrt(h.mindlin.theta));
  }
};

struct HertzLinearTangentialLaw : HertzLawBase {
  static constexpr ContactLaw kLaw = ContactLaw::kHertzLinearTangential;
  static constexpr const char* kName = "hertz_linear_tangential";
  static constexpr bool kNormalHistory = false;
  static constexpr bool kMindlin = false;
  static constexpr bool kBatchable = true;  // branch-free enough for contact_batch.h

  template <int Dim>
  [[gnu::always_inline]] static void advance(ContactHistory<Dim>& h, const ContactKinematics<Dim>& k,
                                             const PairProperties& pair, const ContactParams& p, double dt) {
    const HertzContact c = hertz_contact(k.overlap, pair, p);
    const double stiffness = 8.0 * p.shear_modulus * c.contact_radius;  // Miyata eq. 31
    h.shear = choose(h.touching, h.shear, zero_shear<Dim>()) + stiffness * k.shear_velocity * dt;
    h.touching = true;
    apply_coulomb_limit(h, std::max(0.0, p.friction * c.normal_force + p.cohesion));
  }

  template <int Dim>
  [[gnu::always_inline]] static ContactForces<Dim> forces(const ContactHistory<Dim>& h, const ContactKinematics<Dim>& k,
                                                          const PairProperties& pair, const ContactParams& p) {
    const HertzContact c = hertz_contact(k.overlap, pair, p);
    return hertz_forces(h, k, pair, p, c, 1.0);
  }
};

}  // namespace dem
