// Delta F / F in a region (Cundall & Strack 1979, Table 1, note 2; Randall
// 1989, 6.4.2-6.5.2: quasi-equilibrium judged inside his measurement
// circles).
#include <algorithm>
#include <cmath>
#include <vector>

#include "contact_forces.h"
#include "dem/world.h"
#include "world_state.h"

namespace dem {

template <int Dim>
double BasicWorld<Dim>::out_of_balance(const RegionT<Dim>& region) const {
  const WorldState<Dim>& s = *state_;
  const Particles<Dim>& p = s.particles;
  std::vector<bool> inside(p.slot.size(), false);
  double max_resultant = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!region.contains(p.position[i])) continue;
    inside[p.id[i].index()] = true;
    max_resultant = std::max(max_resultant, (p.force[i] + p.mass[i] * body_acceleration(s, p.position[i])).norm());
  }
  double max_contact_force = 0.0;
  visit_touching_contacts<Dim>(s, [&](const ContactRecordT<Dim>& c) {
    const bool theirs = inside[c.first.index()] || (c.second_particle.valid() && inside[c.second_particle.index()]);
    if (theirs) max_contact_force = std::max(max_contact_force, std::hypot(c.normal_force, c.tangential_force.norm()));
  });
  return max_contact_force > 0.0 ? max_resultant / max_contact_force : 0.0;
}

template double BasicWorld<2>::out_of_balance(const RegionT<2>&) const;
template double BasicWorld<3>::out_of_balance(const RegionT<3>&) const;

}  // namespace dem
