#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "critical_step.h"
#include "law_dispatch.h"
#include "world_state.h"

namespace dem {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
}  // namespace

double rayleigh_time_step(const MaterialDef& m, double radius) {
  const double shear_modulus = m.youngs_modulus / (2.0 * (1.0 + m.poisson_ratio));
  return std::numbers::pi * radius * std::sqrt(m.density / shear_modulus) / (0.1631 * m.poisson_ratio + 0.876605);
}

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

double linear_critical_step(const StepParticle& particle, const ContactParams& c, double normal_dashpot,
                            double shear_dashpot, const DampingDef& damping) {
  const double m = particle.mass, inertia = particle.inertia, r = particle.radius;
  const double local = damping.local_alpha;
  const double local_rotation = damping.local_alpha_rotation.value_or(damping.local_alpha);
  // The rolling spring (rolling_resistance.cpp) turns the particle too.
  const double rolling = 2.25 * c.normal_stiffness * c.rolling_friction * c.rolling_friction * r * r;
  const double turning = c.shear_stiffness * r * r + rolling;
  const double rolling_dashpot = 2.0 * c.rolling_damping_ratio * std::sqrt(rolling * inertia);
  return std::min({mode_critical_step(m, c.normal_stiffness, normal_dashpot, local),
                   mode_critical_step(m, c.shear_stiffness, shear_dashpot, local),
                   mode_critical_step(inertia, turning, shear_dashpot * r * r + rolling_dashpot, local_rotation)});
}

double linear_undamped_critical_step(const StepParticle& particle, const ContactParams& c) {
  double critical = kInfinity;
  const double kn = c.normal_stiffness, ks = c.shear_stiffness, r = particle.radius;
  if (kn > 0.0) critical = std::min(critical, 2.0 * std::sqrt(particle.mass / kn));
  if (ks > 0.0) critical = std::min(critical, 2.0 * std::sqrt(particle.inertia / (ks * r * r)));
  return critical;
}

// For each particle and each contact its material can make, the modes of a
// single contact with a body that does not move (a wall), translation
// (normal and shear) and rotation; the smallest over the assembly. A pair
// of particles moves against each other faster (omega^2 = k / m*), and a
// particle's several contacts stiffen it further: the user's fraction
// covers that. Each law gives its own (Law::critical_time_step): the linear
// laws their modes, the Hertz laws Rayleigh's step.
template <int Dim>
double estimate_critical_time_step(const WorldState<Dim>& state, const ContactParamTable& params,
                                   const DampingDef& damping) {
  const Particles<Dim>& p = state.particles;
  const auto materials = static_cast<std::int32_t>(state.materials.size());
  double critical = kInfinity;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const StepParticle particle{p.mass[i], p.inertia[i], p.radius[i], state.materials[p.material[i]]};
    for (std::int32_t other = 0; other < materials; ++other) {
      const ContactParams& c = params(p.material[i], other);
      if (!c.defined) continue;
      with_law(c.law,
               [&]<typename Law>() { critical = std::min(critical, Law::critical_time_step(particle, c, damping)); });
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
    const StepParticle particle{p.mass[i], p.inertia[i], p.radius[i], state.materials[p.material[i]]};
    for (std::int32_t other = 0; other < materials; ++other) {
      const ContactParams& c = state.params(p.material[i], other);
      if (!c.defined) continue;
      with_law(c.law,
               [&]<typename Law>() { critical = std::min(critical, Law::undamped_critical_time_step(particle, c)); });
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
