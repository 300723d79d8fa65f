// The headless run: case file in, CSV tables and a summary out.
#pragma once

#include <filesystem>
#include <optional>

#include "dem/io/checkpoint_store.h"

namespace dem::run {

struct RunOptions {
  std::filesystem::path case_path;
  std::filesystem::path output_directory;
  std::optional<int> threads;  // overrides the case's numerics.threads
  bool quiet = false;          // no progress line and no summary
  // Periodic checkpoints in <output_directory>/checkpoints (none by default).
  io::CheckpointSettings checkpoints;
  // Continue from the newest checkpoint there into the same tables.
  bool resume = false;
};

// Loads, validates and converts the case, builds the world (2D or 3D, as
// the case declares) and runs every stage, writing the time series each output interval and the snapshots at
// the end. Throws io::CaseError for a bad case, DefinitionError when the
// engine rejects it, std::runtime_error when an output cannot be written or
// there is no checkpoint to resume (or it belongs to another case),
// RunFailure when the run becomes numerically unhealthy.
void run_case(const RunOptions& options);

}  // namespace dem::run
