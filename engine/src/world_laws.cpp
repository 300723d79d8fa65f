#include "world_laws.h"

#include <vector>

#include "contact_laws.h"
#include "dem/law_traits.h"
#include "rolling_resistance.h"

namespace dem {

namespace {

// The columns a table needs for its law, the particles' shape and the energy budget.
ContactColumns columns_for(ContactLaw law, ShapeKind shape, bool energy_budget) {
  const ContactLawTraits traits = contact_law_traits(law).value();
  return {traits.normal_history, traits.mindlin, shape != ShapeKind::kRound, energy_budget};
}

}  // namespace

template <int Dim>
void resolve_laws(WorldState<Dim>& s, const WorldDefT<Dim>& def) {
  std::vector<std::int32_t> wall_materials;
  for (const WallDefT<Dim>& w : def.walls) wall_materials.push_back(w.material.value());
  const WorldLaws laws = resolve_contact_laws(s.materials, s.params, s.particles.material, wall_materials);
  s.pair_law = laws.pair;
  s.wall_law = laws.wall;
  s.contacts.pairs.columns = columns_for(s.pair_law, s.shape, s.energy_budget);
  s.contacts.walls.columns = columns_for(s.wall_law, s.shape, s.energy_budget);
  s.rolling = needs_rolling_resistance(s);
  s.contacts.pairs.columns.rolling = s.contacts.walls.columns.rolling = s.rolling;
}

template void resolve_laws(WorldState<2>&, const WorldDefT<2>&);
template void resolve_laws(WorldState<3>&, const WorldDefT<3>&);

}  // namespace dem
