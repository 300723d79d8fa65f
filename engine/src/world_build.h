// Builds the state a world definition describes (world_build.cpp).
#pragma once

#include "dem/definitions.h"
#include "world_state.h"

namespace dem {

// 0 means what OpenMP would use: OMP_NUM_THREADS if set, else every core.
int resolve_threads(int threads);

// Validates the definition and builds the state it describes, up to (not
// including) the first contact search and force pass.
template <int Dim>
void build_world(WorldState<Dim>& s, const WorldDefT<Dim>& def);

}  // namespace dem
