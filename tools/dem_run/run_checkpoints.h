// dem_run's periodic checkpoints (io/checkpoint_store.h): due every so
// many cycles or wall seconds, taken at an output row whose cycle is also a
// condition check of its stage, so a run resumed from it checks and writes
// at the same cycles as one never interrupted.
#pragma once

#include <string>

#include "dem/io/checkpoint_store.h"
#include "dem/io/snapshot_file.h"
#include "dem/programme.h"
#include "run_recorder.h"

namespace dem::run {

template <int Dim>
class RunCheckpoints {
 public:
  RunCheckpoints(const std::filesystem::path& output_directory, io::CheckpointSettings settings,
                 std::string case_digest, std::uint64_t start_cycle)
      : periodic_(settings) {
    periodic_.begin(output_directory / "checkpoints", std::move(case_digest), start_cycle);
  }

  // At an output row `stage_cycles` into `stage`. Not where the stage's
  // conditions are checked and hold: the stage ends there (after this row).
  bool due(const BasicWorld<Dim>& world, const StageDefT<Dim>& stage, std::uint64_t stage_cycles) const {
    if (!periodic_.store()) return false;
    if (stage_cycles % std::max<std::uint64_t>(stage.until.check_interval, 1) != 0) return false;
    if (stage_cycles >= stage.cycles) return false;  // its end: the next stage's start comes first
    if (has_stop_condition(stage.until) && stage_cycles >= stage.until.min_cycles &&
        stop_conditions_hold(world, stage.until)) {
      return false;
    }
    return periodic_.due(world.cycle_count());
  }

  void write(const BasicWorld<Dim>& world, const io::SnapshotInfo& info, RunRecorder<Dim>& recorder, std::size_t stage,
             std::uint64_t stage_cycles) {
    io::ResumePoint point{.cycle = world.cycle_count(), .stage = stage, .stage_cycles = stage_cycles};
    recorder.fill(point);
    periodic_.write(io::serialize_snapshot(world.snapshot(), info), std::move(point));
  }

 private:
  io::PeriodicCheckpoints periodic_;
};

}  // namespace dem::run
