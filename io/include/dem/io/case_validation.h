// Checks a parsed case before conversion and reports every problem at once,
// each naming the field path ("wall[2].h2: must be greater than h1 (0 <= 0)"),
// so a user fixes a case in one pass rather than one error per run.
#pragma once

#include <string>
#include <vector>

#include "dem/case.pb.h"
#include "dem/io/case_error.h"
#include "dem/io/case_source.h"
#include "dem/io/resource_limits.h"

namespace dem::io {

struct CaseProblem {
  std::string path;     // field path into dem.proto.Case, e.g. "stage[1].wall[0].wall"
  std::string message;  // what is wrong, e.g. "unknown wall \"top\""
};

// Every problem in the case, in the order of its fields; empty when it is
// valid. Besides the schema's rules, every number must lie within what
// double arithmetic can carry (magnitudes from 1e-30 to 1e30, or 0), and
// the threads, particles and packing grids within `limits`.
std::vector<CaseProblem> find_case_problems(const proto::Case& message,
                                            const ResourceLimits& limits = machine_limits());

// Throws CaseError listing every problem, each pointed at its line when the
// source has locations.
void validate_case(const proto::Case& message, const CaseSource& source = {},
                   const ResourceLimits& limits = machine_limits());

}  // namespace dem::io
