// Validation of output.compression, the plate loading analyses (Miyata et
// al. 2002, 3.2-3.3): the plates by name, the states' stress bounds, the
// snapshot stresses and the force distribution's window and classes.
#pragma once

#include "case_names.h"
#include "dem/case.pb.h"
#include "problem_list.h"

namespace dem::io {

void check_compression_output(const proto::CompressionOutput& compression, const NameIndex& walls,
                              ProblemList& problems);

}  // namespace dem::io
