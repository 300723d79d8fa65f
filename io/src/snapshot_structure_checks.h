// The shape of a snapshot message before it is converted: its format tag,
// version and dimension, every array the length its counts imply, ids in
// range, finite numbers; then the value checks of snapshot_checks.h.
#pragma once

#include "dem/io/resource_limits.h"
#include "dem/snapshot.pb.h"
#include "snapshot_problems.h"

namespace dem::io {

template <int Dim>
void check_structure(const proto::Snapshot& message, Problems& problems, const ResourceLimits& limits);

}  // namespace dem::io
