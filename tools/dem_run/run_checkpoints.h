// dem_run's periodic checkpoints (io/checkpoint_store.h): due every so
// many cycles or wall seconds, taken at an output row whose cycle is also a
// condition check of its stage, so a run resumed from it checks and writes
// at the same cycles as one never interrupted.
#pragma once

#include <chrono>
#include <optional>
#include <string>

#include "dem/io/checkpoint_store.h"
#include "dem/io/snapshot_file.h"
#include "dem/io/stop_conditions.h"
#include "dem/programme.h"
#include "run_recorder.h"

namespace dem::run {

template <int Dim>
class RunCheckpoints {
 public:
  RunCheckpoints(const std::filesystem::path& output_directory, io::CheckpointSettings settings, std::string case_digest,
                 std::uint64_t start_cycle)
      : settings_(settings),
        case_digest_(std::move(case_digest)),
        last_cycle_(start_cycle),
        last_time_(std::chrono::steady_clock::now()) {
    if (settings_.enabled()) store_.emplace(output_directory / "checkpoints", settings_.keep);
  }

  // At an output row `stage_cycles` into `stage`. Not where the stage's
  // conditions are checked and hold: the stage ends there (after this row).
  bool due(const BasicWorld<Dim>& world, const StageDefT<Dim>& stage, std::uint64_t stage_cycles) const {
    if (!store_) return false;
    if (stage_cycles % std::max<std::uint64_t>(stage.until.check_interval, 1) != 0) return false;
    if (stage_cycles >= stage.cycles) return false;  // its end: the next stage's start comes first
    if (io::has_stop_condition(stage.until) && stage_cycles >= stage.until.min_cycles &&
        io::stop_conditions_hold(world, stage.until)) {
      return false;
    }
    const bool by_cycles = settings_.cycles > 0 && world.cycle_count() - last_cycle_ >= settings_.cycles;
    const bool by_time = settings_.seconds > 0.0 &&
                         std::chrono::duration<double>(std::chrono::steady_clock::now() - last_time_).count() >=
                             settings_.seconds;
    return by_cycles || by_time;
  }

  void write(const BasicWorld<Dim>& world, const io::SnapshotInfo& info, RunRecorder<Dim>& recorder,
             std::size_t stage, std::uint64_t stage_cycles) {
    io::ResumePoint point;
    point.cycle = world.cycle_count();
    point.stage = stage;
    point.stage_cycles = stage_cycles;
    point.case_digest = case_digest_;
    recorder.fill(point);
    store_->write(io::serialize_snapshot(world.snapshot(), info), point);
    last_cycle_ = world.cycle_count();
    last_time_ = std::chrono::steady_clock::now();
  }

 private:
  io::CheckpointSettings settings_;
  std::string case_digest_;
  std::optional<io::CheckpointStore> store_;
  std::uint64_t last_cycle_;
  std::chrono::steady_clock::time_point last_time_;
};

}  // namespace dem::run
