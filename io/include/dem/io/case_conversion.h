// Turns a case message into engine definitions: materials by name to dense
// ids in order, particle sources expanded in order (so particle ids follow
// the case), wall names to wall ids, and the defaults proto3 cannot spell
// (a 0 that means "unset") filled in.
#pragma once

#include "dem/case.pb.h"
#include "dem/io/case_definition.h"
#include "dem/io/case_error.h"
#include "dem/io/case_source.h"
#include "dem/io/resource_limits.h"

namespace dem::io {

// The dimension a case declares: 2 (also when it leaves dimension out) or 3.
int case_dimension(const proto::Case& message);

// Converts a case of dimension Dim: convert_case(message) reads a 2D case,
// convert_case<3>(message) a 3D one. Validates the case first
// (validate_case), so every caller gets the same checks; throws CaseError
// listing every problem, naming the particle source the generators could
// not place or the particle file that could not be read, or naming
// `dimension` when the case declares the other one. The case must keep
// within `limits` (resource_limits.h), particle files included.
template <int Dim = 2>
CaseDefinitionT<Dim> convert_case(const proto::Case& message, const CaseSource& source = {},
                                  const ResourceLimits& limits = machine_limits());

extern template CaseDefinitionT<2> convert_case<2>(const proto::Case&, const CaseSource&, const ResourceLimits&);
extern template CaseDefinitionT<3> convert_case<3>(const proto::Case&, const CaseSource&, const ResourceLimits&);

// Converts a case in the dimension it declares.
AnyCaseDefinition convert_any_case(const proto::Case& message, const CaseSource& source = {},
                                   const ResourceLimits& limits = machine_limits());

}  // namespace dem::io
