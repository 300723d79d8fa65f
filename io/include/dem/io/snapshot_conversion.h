// Snapshots between the engine and Protocol Buffers (idl/dem/snapshot.proto):
// dem::WorldSnapshotT<Dim> <-> dem.proto.Snapshot, every double as the
// engine holds it, so a restored world continues bit for bit. Written once
// over the dimension, instantiated for 2 and 3.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "dem/io/resource_limits.h"
#include "dem/snapshot.h"
#include "dem/snapshot.pb.h"

namespace dem::io {

// A snapshot that cannot be read or is not consistent: the message names
// the source and the field ("run.snapshot: particles.radius[12]: must be > 0").
class SnapshotError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What a snapshot records beside the engine's state.
struct SnapshotInfo {
  std::string case_name;
  std::string description;
};

inline constexpr const char* kSnapshotFormat = "dem.snapshot";
inline constexpr unsigned kSnapshotVersion = 1;

template <int Dim>
proto::Snapshot snapshot_to_proto(const WorldSnapshotT<Dim>& snapshot, const SnapshotInfo& info);

// Checks the message - its format tag and version, its dimension (Dim),
// that every array has the length its counts imply, ids in range, finite
// numbers within what the force arithmetic carries, known enum values, no
// duplicate wall or material names, threads and particles within `limits`
// - and converts it. Throws SnapshotError listing what is wrong (at most a
// dozen problems). The World constructor then checks the physics
// (DefinitionError).
template <int Dim>
WorldSnapshotT<Dim> snapshot_from_proto(const proto::Snapshot& message, SnapshotInfo* info = nullptr,
                                        const ResourceLimits& limits = machine_limits());

// Every entry of the snapshot's field lists (dem/snapshot_fields.h) against
// the schema, as the conversion finds them: one line per entry with no
// field of its name or a field that cannot carry its type (the conversion
// throws std::logic_error at the first). Empty when they agree; the io
// tests check it, so a list line without its schema field fails there.
template <int Dim>
std::vector<std::string> snapshot_schema_problems(int* fields_checked = nullptr);

extern template proto::Snapshot snapshot_to_proto<2>(const WorldSnapshotT<2>&, const SnapshotInfo&);
extern template proto::Snapshot snapshot_to_proto<3>(const WorldSnapshotT<3>&, const SnapshotInfo&);
extern template WorldSnapshotT<2> snapshot_from_proto<2>(const proto::Snapshot&, SnapshotInfo*, const ResourceLimits&);
extern template WorldSnapshotT<3> snapshot_from_proto<3>(const proto::Snapshot&, SnapshotInfo*, const ResourceLimits&);
extern template std::vector<std::string> snapshot_schema_problems<2>(int*);
extern template std::vector<std::string> snapshot_schema_problems<3>(int*);

}  // namespace dem::io
