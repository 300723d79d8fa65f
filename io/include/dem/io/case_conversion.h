// Turns a case message into engine definitions: materials by name to dense
// ids in order, particle sources expanded in order (so particle ids follow
// the case), wall names to wall ids, and the defaults proto3 cannot spell
// (a 0 that means "unset") filled in.
#pragma once

#include "dem/case.pb.h"
#include "dem/io/case_definition.h"
#include "dem/io/case_error.h"
#include "dem/io/case_source.h"

namespace dem::io {

// Validates the case first (validate_case), so every caller gets the same
// checks; throws CaseError listing every problem, or naming the particle
// source the generators could not place.
CaseDefinition convert_case(const proto::Case& message, const CaseSource& source = {});

}  // namespace dem::io
