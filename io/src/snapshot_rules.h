// The rules a case's values obey, applied to a decoded snapshot: a payload
// edited and signed again carries the right checksum, so only these stand
// between it and a world built from values no case could give (a zero or
// negative stiffness, Poisson's ratio 2, a zero quaternion). Each problem
// names the snapshot's field; the ranges are the case validation's
// (the rules of case_rules.h and problem_list.h), so a snapshot holds
// exactly what a case may.
#pragma once

#include <cstdint>

#include "dem/snapshot.pb.h"
#include "snapshot_problems.h"

namespace dem::io {

// The largest cycle a snapshot may stand at: 2^62. A run picked up there
// has 2^62 (4.6e18) cycles left before the 64-bit counter wraps - 146,000
// years at a million cycles a second - so a counter read from a snapshot
// can never wrap in a run, and every cycle number (formed_cycle,
// sorted_cycle, tables, checkpoints) stays ordered.
inline constexpr std::uint64_t kLargestSnapshotCycle = std::uint64_t{1} << 62;

// Call once the structure checks passed (array lengths, ids in range).
template <int Dim>
void check_case_rules(const proto::Snapshot& message, Problems& problems);

}  // namespace dem::io
