// Checks of a world just built from a case, for what only the engine can
// work out: its critical time step. dem_run, dem_server and the fuzz
// targets call it between building a world and running it.
#pragma once

#include <vector>

#include "dem/io/case_error.h"
#include "dem/io/case_source.h"
#include "dem/programme.h"
#include "dem/world.h"

namespace dem::io {

// Throws CaseError naming time_step.fixed when a fixed step exceeds the
// critical step the engine estimates (2 sqrt(m/k) for the linear laws,
// Rayleigh's for the Hertz laws, over every particle and the stiffest
// contact it can meet, shortened by the contact dashpots and local damping:
// BasicWorld::critical_time_step): central differences are unstable beyond
// it, and the run would blow up. Also refuses a step that is not a finite
// number > 0.
template <int Dim>
void check_built_world(const BasicWorld<Dim>& world, const CaseSource& source = {});
// And each stage's fixed step (stage[i].time_step.fixed, or the one kept
// from before) under the damping in force from its start on (its own
// damping, or the one kept): the masses and stiffnesses no stage changes,
// its damping moves the critical step.
template <int Dim>
void check_built_world(const BasicWorld<Dim>& world, const std::vector<StageDefT<Dim>>& stages,
                       const CaseSource& source = {});

extern template void check_built_world<2>(const BasicWorld<2>&, const CaseSource&);
extern template void check_built_world<3>(const BasicWorld<3>&, const CaseSource&);
extern template void check_built_world<2>(const BasicWorld<2>&, const std::vector<StageDefT<2>>&, const CaseSource&);
extern template void check_built_world<3>(const BasicWorld<3>&, const std::vector<StageDefT<3>>&, const CaseSource&);

}  // namespace dem::io
