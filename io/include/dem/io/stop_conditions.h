// Whether a stage's stop conditions hold now - the engine's own rule
// (engine/src/programme.cpp, conditions_hold), which it does not export.
// A checkpoint taken at a condition check must know it: the engine checks
// after the output row, so a run resumed from a checkpoint where the
// conditions held would run past the stage's end. Keep the two alike; the
// engine exporting its function would retire this copy.
#pragma once

#include "dem/programme.h"

namespace dem::io {

template <int Dim>
bool stop_conditions_hold(const BasicWorld<Dim>& world, const StopConditions& until);

// Whether any condition is set (a stage without any runs its cycles).
bool has_stop_condition(const StopConditions& until);

extern template bool stop_conditions_hold(const BasicWorld<2>&, const StopConditions&);
extern template bool stop_conditions_hold(const BasicWorld<3>&, const StopConditions&);

}  // namespace dem::io
