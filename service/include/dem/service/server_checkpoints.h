// The server's periodic checkpoints (io/checkpoint_store.h) in
// <output>/<case>/checkpoints: due every so many cycles or wall seconds
// (a programme's by default, a command's when the options ask),
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
  // `settings` for cycle and run_until; `programme_settings` for programmes
  // (the one-shot mode and run_programme), which checkpoint by default
  // (io::default_programme_checkpoints, unless the options say otherwise).
  ServerCheckpoints(io::CheckpointSettings settings, io::CheckpointSettings programme_settings)
      : commands_(settings), programme_(programme_settings) {}

  // A world was loaded: its checkpoints go in `case_directory`/checkpoints
  // (none when it is empty).
  void begin(const std::filesystem::path& case_directory, std::string case_digest, std::uint64_t cycle);
  // A programme starts at `cycle`, or ends there: its own settings apply in between.
  void begin_programme(std::uint64_t cycle);
  void end_programme(std::uint64_t cycle);
  bool due(std::uint64_t cycle) const { return active().due(cycle); }
  // `stage`, `stage_cycles`: where a programme stands (0, 0 outside one).
  void write(const WorldSession& world, const io::SnapshotInfo& info, OutputRecorder& recorder, std::size_t stage,
             std::uint64_t stage_cycles);

 private:
  const io::PeriodicCheckpoints& active() const { return in_programme_ ? programme_ : commands_; }
  io::PeriodicCheckpoints& active() { return in_programme_ ? programme_ : commands_; }

  io::PeriodicCheckpoints commands_;
  io::PeriodicCheckpoints programme_;
  bool in_programme_ = false;
  std::filesystem::path directory_;  // <case>/checkpoints, or empty: none
  std::string case_digest_;
};

}  // namespace dem::service
