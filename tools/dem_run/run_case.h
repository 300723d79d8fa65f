// The headless run: case file in, CSV tables and a summary out.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "dem/io/checkpoint_store.h"

namespace dem::run {

struct RunOptions {
  std::filesystem::path case_path;
  std::filesystem::path output_directory;
  std::optional<int> threads;                 // overrides the case's numerics.threads
  std::optional<std::uint64_t> vtk_interval;  // overrides the case's output.vtk_interval (0: none)
  bool quiet = false;                         // no progress line and no summary
  // Periodic checkpoints in <output_directory>/checkpoints (none by default).
  io::CheckpointSettings checkpoints;
  // Continue from the newest checkpoint there into the same tables.
  bool resume = false;
  // Start afresh into an output directory that holds an earlier run's
  // tables, snapshots, ParaView files and checkpoints, removing them first.
  bool overwrite = false;
};

// A fresh run (not resume, not overwrite) into a directory holding an
// earlier run's outputs: refused before anything is written.
struct OutputInUse : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class RunOutcome {
  kCompleted,    // every stage ran
  kInterrupted,  // Ctrl-C or SIGTERM stopped it; the tables and final.snapshot hold the state reached
};

// Loads, validates and converts the case, builds the world (2D or 3D, as
// the case declares) and runs every stage, writing the time series each
// output interval, and at the end the contact and particle tables and
// final.snapshot (the whole state, for demctl snapshot load or dem_vtk) -
// also when interrupted. Throws io::CaseError for a bad case,
// DefinitionError when the engine rejects it, std::runtime_error when an
// output cannot be written or there is no checkpoint to resume (or it
// belongs to another case), RunFailure when the run becomes numerically
// unhealthy, OutputInUse when --out holds an earlier run's outputs.
RunOutcome run_case(const RunOptions& options);

}  // namespace dem::run
