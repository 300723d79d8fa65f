// The server's periodic checkpoints (io/checkpoint_store.h) in
// <output>/<case>/checkpoints: due every so many cycles or wall seconds,
// written by the engine thread between chunks (a cycle or run_until) or
// at an output row of a programme where the stage can be resumed as if
// never interrupted. A server started with --case FILE --resume continues
// from the newest (docs/RELIABILITY.md).
#pragma once

#include <string>

#include "dem/io/checkpoint_store.h"
#include "dem/io/snapshot_conversion.h"
#include "dem/service/output_recorder.h"
#include "dem/service/world_session.h"

namespace dem::service {

class ServerCheckpoints {
 public:
  explicit ServerCheckpoints(io::CheckpointSettings settings) : periodic_(settings) {}

  // A world was loaded: its checkpoints go in `case_directory`/checkpoints
  // (none when it is empty).
  void begin(const std::filesystem::path& case_directory, std::string case_digest, std::uint64_t cycle);
  bool due(std::uint64_t cycle) const { return periodic_.due(cycle); }
  // `stage`, `stage_cycles`: where a programme stands (0, 0 outside one).
  void write(const WorldSession& world, const io::SnapshotInfo& info, OutputRecorder& recorder, std::size_t stage,
             std::uint64_t stage_cycles);

 private:
  io::PeriodicCheckpoints periodic_;
};

}  // namespace dem::service
