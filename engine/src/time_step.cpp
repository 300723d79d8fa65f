#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "world_state.h"

namespace dem {

namespace {

// Randall (1989) 4.33-4.34: the time for a Rayleigh wave to cross a
// particle, dt = pi R sqrt(rho / G) / (0.1631 nu + 0.876605).
double rayleigh_time_step(const MaterialDef& m, double radius) {
  const double shear_modulus = m.youngs_modulus / (2.0 * (1.0 + m.poisson_ratio));
  return std::numbers::pi * radius * std::sqrt(m.density / shear_modulus) / (0.1631 * m.poisson_ratio + 0.876605);
}

}  // namespace

// Linear laws, Cundall & Strack (Motion): the critical step of a mass m on
// a spring k is 2 sqrt(m/k). For each particle we take the stiffest contact
// its material can make, for translation (m, k_n) and rotation (I, k_s R^2).
// Hertz laws: the Rayleigh time step of the particle (Randall 4.33). The
// smallest over the assembly; the user's fraction covers several contacts.
template <int Dim>
double estimate_critical_time_step(const WorldState<Dim>& state) {
  const Particles<Dim>& p = state.particles;
  const auto materials = static_cast<std::int32_t>(state.materials.size());
  double critical = std::numeric_limits<double>::infinity();
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

template double estimate_critical_time_step(const WorldState<2>&);
template double estimate_critical_time_step(const WorldState<3>&);

}  // namespace dem
