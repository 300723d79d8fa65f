#include <algorithm>
#include <cmath>
#include <limits>

#include "world_state.h"

namespace dem {

// Cundall & Strack (Motion): the critical step of a mass m on a spring k is
// 2 sqrt(m/k). For each particle we take the stiffest contact its material
// can make, for translation (m, k_n) and rotation (I, k_s R^2), and keep the
// smallest over the assembly. The user's fraction covers several contacts.
template <int Dim>
double estimate_critical_time_step(const WorldState<Dim>& state) {
  const Particles<Dim>& p = state.particles;
  const auto materials = static_cast<MaterialId>(state.materials.size());
  double critical = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.size(); ++i) {
    double kn = 0.0, ks = 0.0;
    for (MaterialId other = 0; other < materials; ++other) {
      const ContactParams& c = state.params(p.material[i], other);
      if (!c.defined) continue;
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
