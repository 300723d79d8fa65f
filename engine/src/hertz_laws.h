// Hertz normal force with two tangential laws: Mindlin-Deresiewicz with its
// loading history (Randall 1989) and the linear-pressure-dependent
// stiffness 8 G* a (Miyata et al. 2002, eq. 31).
#pragma once

#include <algorithm>
#include <cmath>

#include "contact_kinematics.h"
#include "contact_params.h"
#include "contact_table.h"
#include "mindlin.h"
#include "tangential.h"

namespace dem {

// The normal part both Hertz laws share. Randall codes Hertz incrementally
// (4.11-4.12), which drifts from the curve it integrates; we use the curve
// itself, N = 4/3 E* (R* alpha^3)^(1/2) = 4/3 E* a alpha with a = (R* alpha)^(1/2)
// (Randall 3.12-3.13; Miyata eq. 24), and its change over the step.
struct HertzNormal {
  double contact_radius;  // a
  double force_change;    // dN
  double stiffness;       // dN/d(alpha) = 2 E* a (Randall 3.15)
};

template <int Dim>
HertzNormal apply_hertz_normal(ContactState<Dim>& s, const ContactKinematics<Dim>& k, const PairProperties& pair,
                               const ContactParams& p) {
  const double previous = s.touching ? s.normal_force : 0.0;
  const double a = std::sqrt(pair.effective_radius * k.overlap);  // (3.12)
  s.normal_force = 4.0 / 3.0 * p.contact_modulus * a * k.overlap;  // (3.13)
  s.overlap = k.overlap;
  const double stiffness = 2.0 * p.contact_modulus * a;
  // Damping as a fraction beta of critical (4.13): 2 beta sqrt(m* 2 E* a) n_dot.
  s.normal_damping = 2.0 * p.damping_ratio * std::sqrt(pair.effective_mass * stiffness) * k.normal_velocity;
  return {a, s.normal_force - previous, stiffness};
}

// Tangential dashpot on a tangential stiffness (Randall 4.19), off unless asked for.
template <int Dim>
ShearForce<Dim> tangential_dashpot(const ContactState<Dim>& s, const ContactKinematics<Dim>& k,
                                   const PairProperties& pair, const ContactParams& p, double stiffness) {
  if (!p.tangential_damping || s.sliding) return zero_shear<Dim>();
  return ShearForce<Dim>(2.0 * p.damping_ratio * std::sqrt(pair.effective_mass * stiffness) * k.shear_velocity);
}

struct HertzMindlinLaw {
  template <int Dim>
  static void apply(ContactState<Dim>& s, const ContactKinematics<Dim>& k, const PairProperties& pair,
                    const ContactParams& p, double dt) {
    if (!s.touching) {
      s.shear = zero_shear<Dim>();
      s.mindlin = MindlinHistory{};
      s.mindlin_axis = Vec<Dim>::Zero();
    }
    const HertzNormal n = apply_hertz_normal(s, k, pair, p);
    s.touching = true;
    const ShearForce<Dim> ds = k.shear_velocity * dt;
    const double mu = p.friction;
    double theta;
    if constexpr (Dim == 2) {
      // F_s along t_i is the law's signed T.
      theta = mindlin_step(s.mindlin, s.shear, s.normal_force, n.force_change, n.contact_radius, ds, mu,
                           p.shear_modulus);
    } else {
      // In 3D the law runs along a loading axis in the tangent plane, set
      // by the first tangential displacement and turned with the contact;
      // displacement across the axis meets the current stiffness 8 G* a theta.
      Vec3& axis = s.mindlin_axis;
      axis -= axis.dot(k.normal) * k.normal;
      if (axis.squaredNorm() < 1e-24) {
        axis = ds.norm() > 0.0 ? Vec3(ds.normalized()) : Vec3::Zero();
      } else {
        axis.normalize();
      }
      double along = s.shear.dot(axis);
      const Vec3 across = s.shear - along * axis;
      const double ds_along = ds.dot(axis);
      theta = mindlin_step(s.mindlin, along, s.normal_force, n.force_change, n.contact_radius, ds_along, mu,
                           p.shear_modulus);
      s.shear = along * axis + across + 8.0 * p.shear_modulus * n.contact_radius * theta * (ds - ds_along * axis);
    }
    const double limit = std::max(0.0, mu * s.normal_force + p.cohesion);
    // With theta = 0 the law lands exactly on mu N: full slip (Randall 3.95), so
    // reaching the limit counts as sliding, not only passing it.
    const double magnitude = shear_magnitude(s.shear);
    s.sliding = magnitude > limit || (limit > 0.0 && magnitude >= limit * (1.0 - 1e-12));
    if (s.sliding) {
      clamp_shear(s.shear, limit);
      if constexpr (Dim == 2) {
        mindlin_slide(s.mindlin, s.shear);
      } else {
        if (limit > 0.0) s.mindlin_axis = s.shear.normalized();
        mindlin_slide(s.mindlin, limit);
      }
    }
    s.shear_damping = tangential_dashpot(s, k, pair, p, 8.0 * p.shear_modulus * n.contact_radius * theta);
  }
};

struct HertzLinearTangentialLaw {
  template <int Dim>
  static void apply(ContactState<Dim>& s, const ContactKinematics<Dim>& k, const PairProperties& pair,
                    const ContactParams& p, double dt) {
    if (!s.touching) s.shear = zero_shear<Dim>();
    const HertzNormal n = apply_hertz_normal(s, k, pair, p);
    s.touching = true;
    const double stiffness = 8.0 * p.shear_modulus * n.contact_radius;  // Miyata eq. 31
    s.shear += stiffness * k.shear_velocity * dt;
    const double limit = std::max(0.0, p.friction * s.normal_force + p.cohesion);
    apply_coulomb_limit(s, limit);
    s.shear_damping = tangential_dashpot(s, k, pair, p, stiffness);
  }
};

}  // namespace dem
