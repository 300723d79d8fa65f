#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "world_state.h"

namespace dem {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Randall (1989) 4.33-4.34: the time for a Rayleigh wave to cross a
// particle, dt = pi R sqrt(rho / G) / (0.1631 nu + 0.876605).
double rayleigh_time_step(const MaterialDef& m, double radius) {
  const double shear_modulus = m.youngs_modulus / (2.0 * (1.0 + m.poisson_ratio));
  return std::numbers::pi * radius * std::sqrt(m.density / shear_modulus) / (0.1631 * m.poisson_ratio + 0.876605);
}

}  // namespace

// The contact dashpots (Cundall & Strack eqs. 26-28, Miyata eq. 17, Randall
// 4.13 and 4.19, the rolling dashpot) act on the relative velocity the last
// step left, v(t - dt/2). A mass m on a spring k with such a dashpot c,
// integrated by central differences (eqs. 23-24),
//   m (x+ - 2x + x-) / dt^2 + c (x - x-) / dt + k x = 0,
// has the characteristic polynomial z^2 - (2 - 2 zeta h - h^2) z + (1 - 2 zeta h)
// with h = omega dt, omega^2 = k/m, zeta = c / (2 sqrt(k m)). Both roots lie
// in the unit circle (Jury's conditions) while h^2 + 4 zeta h < 4:
//   omega dt < 2 (sqrt(1 + zeta^2) - zeta),
// 2 at zeta = 0, and less with every dashpot.
double damped_step_factor(double zeta) { return std::sqrt(1.0 + zeta * zeta) - zeta; }

// Global damping (eq. 34) is taken at the middle of the step (eqs. 35-36:
// v' = (v (1 - alpha dt/2) + F dt/m) / (1 + alpha dt/2)), which leaves the
// limit where it was: the polynomial becomes (1 + g) z^2 - (2 - 2 zeta h - h^2) z
// + (1 - g - 2 zeta h), g = alpha dt / 2, and Jury's conditions are the same.
// Local damping (Miyata eq. 33) adds alpha of the force's size against the
// motion: while the spring holds the particle back it is a spring of
// (1 + alpha) k, and a step too long for that spring grows every swing.
double mode_critical_step(double mass, double stiffness, double dashpot, double local) {
  if (!(stiffness > 0.0) || !(mass > 0.0)) return kInfinity;
  const double k = (1.0 + local) * stiffness;
  const double zeta = dashpot / (2.0 * std::sqrt(k * mass));
  return 2.0 * std::sqrt(mass / k) * damped_step_factor(zeta);
}

// For each particle and each contact its material can make, the modes of a
// single contact with a body that does not move (a wall), translation
// (normal and shear) and rotation; the smallest over the assembly. A pair
// of particles moves against each other faster (omega^2 = k / m*), and a
// particle's several contacts stiffen it further: the user's fraction
// covers that.
// Linear laws: omega^2 = k_n / m, k_s / m, (k_s R^2 + k_roll) / I (Cundall &
// Strack, Motion: 2 sqrt(m/k) undamped). Hertz laws: the Rayleigh time step
// of the particle (Randall 4.33), as it is: Randall takes it as the step
// itself, with dashpots at 10-20 % of critical (his hopper and pluvial
// runs). It is a wave's crossing time, not a contact's limit: a Hertz
// contact stiffens with its overlap (k_n = 2 E* a), and at the overlaps of
// such runs its own limit lies above the Rayleigh step - which a dashpot
// shortens, and a step set from the Rayleigh step does not follow.
template <int Dim>
double estimate_critical_time_step(const WorldState<Dim>& state, const ContactParamTable& params,
                                   const DampingDef& damping) {
  const Particles<Dim>& p = state.particles;
  const auto materials = static_cast<std::int32_t>(state.materials.size());
  const double local = damping.local_alpha;
  const double local_rotation = damping.local_alpha_rotation.value_or(damping.local_alpha);
  double critical = kInfinity;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double m = p.mass[i], inertia = p.inertia[i], r = p.radius[i];
    for (std::int32_t other = 0; other < materials; ++other) {
      const ContactParams& c = params(p.material[i], other);
      if (!c.defined) continue;
      if (c.law == ContactLaw::kHertzMindlin || c.law == ContactLaw::kHertzLinearTangential) {
        critical = std::min(critical, rayleigh_time_step(state.materials[p.material[i]], r));
        continue;
      }
      const bool restitution = c.law == ContactLaw::kLinearRestitution;
      // Miyata eq. 17 with the mass against a wall (m* = m); eq. 28 otherwise.
      const double normal_dashpot = restitution ? c.restitution_viscosity * std::sqrt(m) : c.normal_viscosity;
      const double shear_dashpot = restitution ? 0.0 : c.shear_viscosity;
      // The rolling spring (rolling_resistance.cpp) turns the particle too.
      const double rolling = 2.25 * c.normal_stiffness * c.rolling_friction * c.rolling_friction * r * r;
      const double turning = c.shear_stiffness * r * r + rolling;
      const double rolling_dashpot = 2.0 * c.rolling_damping_ratio * std::sqrt(rolling * inertia);
      critical =
          std::min({critical, mode_critical_step(m, c.normal_stiffness, normal_dashpot, local),
                    mode_critical_step(m, c.shear_stiffness, shear_dashpot, local),
                    mode_critical_step(inertia, turning, shear_dashpot * r * r + rolling_dashpot, local_rotation)});
    }
  }
  return critical;
}

template <int Dim>
double estimate_critical_time_step(const WorldState<Dim>& state) {
  return estimate_critical_time_step(state, state.params, state.damping);
}

// Undamped, as Cundall & Strack (Motion) give it: 2 sqrt(m/k) for the
// stiffest contact a particle's material can make, translation (m, k_n)
// and rotation (I, k_s R^2); Hertz laws: the Rayleigh time step (Randall
// 4.33). A time step fraction is of this, so the steps of cases given as
// fractions stay what they were before the damping counted.
template <int Dim>
double estimate_undamped_critical_time_step(const WorldState<Dim>& state) {
  const Particles<Dim>& p = state.particles;
  const auto materials = static_cast<std::int32_t>(state.materials.size());
  double critical = kInfinity;
  for (std::size_t i = 0; i < p.size(); ++i) {
    double kn = 0.0, ks = 0.0;
    for (std::int32_t other = 0; other < materials; ++other) {
      const ContactParams& c = state.params(p.material[i], other);
      if (!c.defined) continue;
      if (c.law == ContactLaw::kHertzMindlin || c.law == ContactLaw::kHertzLinearTangential) {
        critical = std::min(critical, rayleigh_time_step(state.materials[p.material[i]], p.radius[i]));
        continue;
      }
      kn = std::max(kn, c.normal_stiffness);
      ks = std::max(ks, c.shear_stiffness);
    }
    if (kn > 0.0) critical = std::min(critical, 2.0 * std::sqrt(p.mass[i] / kn));
    if (ks > 0.0) {
      critical = std::min(critical, 2.0 * std::sqrt(p.inertia[i] / (ks * p.radius[i] * p.radius[i])));
    }
  }
  return critical;
}

template double estimate_critical_time_step(const WorldState<2>&, const ContactParamTable&, const DampingDef&);
template double estimate_critical_time_step(const WorldState<3>&, const ContactParamTable&, const DampingDef&);
template double estimate_critical_time_step(const WorldState<2>&);
template double estimate_critical_time_step(const WorldState<3>&);
template double estimate_undamped_critical_time_step(const WorldState<2>&);
template double estimate_undamped_critical_time_step(const WorldState<3>&);

}  // namespace dem
