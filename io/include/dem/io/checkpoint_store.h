// Periodic checkpoints of a run, for crash recovery (docs/RELIABILITY.md):
// in a directory, each checkpoint is a snapshot (checksummed frame, written
// with fsync and renamed into place) and a resume file naming where the
// run stood - the stage, the cycles done in it, how long each table was,
// the plate loading analyses' state, the ParaView steps written - written the same way after it, so a
// checkpoint whose resume file exists is whole. The last `keep` are kept.
// A run restarted with --resume takes the newest whole one (an older one
// when the newest is damaged) and continues from it, bit for bit, into the
// same tables.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "dem/io/csv_file.h"
#include "dem/io/vtk_series.h"

namespace dem::io {

// Where a run stood at a checkpoint, beyond the world's state.
struct ResumePoint {
  std::uint64_t cycle = 0;                 // the world's cycle (the snapshot's)
  std::size_t stage = 0;                   // the stage running, from 0
  std::uint64_t stage_cycles = 0;          // of it run; 0: the stage has not started (its start actions are to come)
  std::string case_digest;                 // SHA-256 of the case's bytes, hex: --resume refuses another case
  TableSizes tables;                       // each table's length
  std::string analysis;                    // the plate loading analyses' state as text (compression_state.h), or empty
  std::vector<VtkSeries::Step> vtk_steps;  // the ParaView series' steps so far (none: no series yet)
};

// When a checkpoint is due: every `cycles` cycles and/or every `seconds`
// of wall time, whichever comes first (0 turns either off; both 0: none);
// the first one after `first_seconds` of wall time when that is set, so a
// long interval does not leave a run's start unprotected.
struct CheckpointSettings {
  std::uint64_t cycles = 0;
  double seconds = 0.0;
  int keep = 3;
  double first_seconds = 0.0;
  bool enabled() const { return cycles > 0 || seconds > 0.0 || first_seconds > 0.0; }
};

// What a programme run (dem_run, dem_server's one-shot mode and
// run_programme) checkpoints when not told: a first checkpoint 5 s of wall
// time after its start, then every 5 minutes: a killed run loses at most
// that much work, and a run killed early has something to resume from.
inline CheckpointSettings default_programme_checkpoints() {
  return CheckpointSettings{.cycles = 0, .seconds = 300.0, .keep = 3, .first_seconds = 5.0};
}

class CheckpointStore {
 public:
  // Creates the directory when it is missing.
  CheckpointStore(std::filesystem::path directory, int keep);

  // Writes a checkpoint (the snapshot's framed bytes and where the run
  // stood) and deletes all but the newest `keep`. Throws SnapshotError
  // naming the file when it cannot be written.
  void write(std::string_view snapshot_bytes, const ResumePoint& point);

  struct Latest {
    std::string snapshot_bytes;  // framed, its checksum already checked
    ResumePoint point;
    std::filesystem::path path;  // the snapshot's file
  };
  // The newest whole checkpoint, skipping damaged ones; nothing when none is.
  std::optional<Latest> latest() const;

  const std::filesystem::path& directory() const { return directory_; }

 private:
  std::filesystem::path directory_;
  int keep_;
};

// What dem_run and dem_server share: a run's store, and when its next
// checkpoint is due - once `settings.cycles` cycles or `settings.seconds`
// of wall time have passed since it began or since the last checkpoint.
// Where in a stage a checkpoint may be taken is the caller's to say.
class PeriodicCheckpoints {
 public:
  explicit PeriodicCheckpoints(CheckpointSettings settings) : settings_(settings) {}

  // A run begins (again) at `cycle`; its checkpoints go in `directory`
  // (none when it is empty or the settings turn them off), each stamped
  // with `case_digest`.
  void begin(const std::filesystem::path& directory, std::string case_digest, std::uint64_t cycle);
  bool due(std::uint64_t cycle) const;
  // Writes a checkpoint (the point's case digest filled in) and starts the
  // next interval at its cycle. Only when the run has a store (due()).
  void write(std::string_view snapshot_bytes, ResumePoint point);

  const CheckpointStore* store() const { return store_ ? &*store_ : nullptr; }

 private:
  CheckpointSettings settings_;
  std::optional<CheckpointStore> store_;
  std::string case_digest_;
  std::uint64_t last_cycle_ = 0;
  std::chrono::steady_clock::time_point last_time_;
  bool written_ = false;  // since begin()
};

// The resume file's text, and back (throws std::runtime_error naming what is wrong).
std::string resume_text(const ResumePoint& point);
ResumePoint parse_resume(std::string_view text);

// SHA-256 of a file's bytes, or of bytes, as hex, for ResumePoint::case_digest.
std::string file_digest(const std::filesystem::path& path);
std::string bytes_digest(std::string_view bytes);

}  // namespace dem::io
