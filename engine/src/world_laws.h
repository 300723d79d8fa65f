// Which contact law a world's pairs and walls use (contact_laws.h) and so
// which columns its contact table keeps.
#pragma once

#include "dem/definitions.h"
#include "world_state.h"

namespace dem {

// Sets s.pair_law, s.wall_law, s.rolling and the tables' columns from the
// materials, contact models and particle shapes already in s.
template <int Dim>
void resolve_laws(WorldState<Dim>& s, const WorldDefT<Dim>& def);

}  // namespace dem
