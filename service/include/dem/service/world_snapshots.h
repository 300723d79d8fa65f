// A session's world as snapshots: the framed, serialized dem.proto.Snapshot
// of the state now (save_snapshot, checkpoints, a programme's final
// snapshot), a copy kept in memory to write or go back to later (a run's
// last good state), and a snapshot's state put back into the session. They
// read the world through on_world and replace it only through
// WorldSession::restore.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>

#include "dem/io/snapshot_conversion.h"
#include "dem/service/world_session.h"

namespace dem::service {

// The serialized snapshot of the world now (io::serialize_snapshot).
std::string snapshot_bytes(const WorldSession& world, const io::SnapshotInfo& info);

// Replaces the session's world by a framed snapshot's of its dimension (a
// checkpoint of the case it runs). Throws SnapshotError or DefinitionError.
void restore_bytes(WorldSession& world, std::string_view bytes, const std::string& source);

// The whole state at one cycle, copied in memory (the engine's snapshot),
// so it can be written or put back later: a run that fails writes its last
// good one and goes back to it.
class StateCheckpoint {
 public:
  explicit StateCheckpoint(const WorldSession& world);

  std::uint64_t cycle() const;
  std::string bytes(const io::SnapshotInfo& info) const;  // a serialized dem.proto.Snapshot
  // Puts `world` (the session it was taken from) back to it.
  // std::bad_variant_access, with nothing changed, for a session of the
  // other dimension.
  void restore(WorldSession& world) const;

 private:
  std::variant<WorldSnapshotT<2>, WorldSnapshotT<3>> state_;
};

}  // namespace dem::service
