// Checks of a snapshot's values that snapshot_conversion.cpp's shape
// checks (array lengths, ids in range) leave out: every enum a known
// value, every double finite and within what the force arithmetic carries,
// no two walls or materials of one name, thread and particle counts within
// the machine's limits. Each problem names its field.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "dem/io/resource_limits.h"
#include "dem/snapshot.pb.h"

namespace dem::io {

// (field path, what is wrong) for each problem, in the order of the fields.
std::vector<std::pair<std::string, std::string>> snapshot_value_problems(const proto::Snapshot& message,
                                                                         const ResourceLimits& limits);

}  // namespace dem::io
