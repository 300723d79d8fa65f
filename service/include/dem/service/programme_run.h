// The case's loading programme as a one-shot server runs it
// (dem_server --case FILE --run-and-exit, or the run_programme command): which stage is running and how
// far, when the time series is due a row, the last state known to be good,
// and how the programme ended. The engine's run_stage does the stepping and
// decides each stage's end; this is only the bookkeeping around it.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "dem/service/health_watch.h"
#include "dem/service/world_session.h"

namespace dem::service {

enum class ProgrammeOutcome {
  kRunning,
  kCompleted,  // every stage ran
  kStopped,    // ended early by a stop or shutdown command, SIGINT or SIGTERM
  kFailed,     // the engine failed or blew up, or an output could not be written
};

class ProgrammeRun {
 public:
  // `output_interval`: cycles between rows of the time series, counted from
  // each stage's start as dem_run counts them (the case's output.interval);
  // the stages run are first .. first + count - 1 (from 0).
  ProgrammeRun(const WorldSession& world, std::uint64_t output_interval, std::size_t first, std::size_t count);

  std::size_t stage_count() const { return stage_count_; }
  std::size_t stage() const { return stage_; }  // the stage running, or stage_count() after the last
  // `done`: cycles of it run already (a resumed checkpoint's).
  void start_stage(std::size_t stage, const WorldSession& world, std::uint64_t done = 0);
  std::uint64_t stage_cycles(std::uint64_t cycle) const { return cycle - stage_start_; }

  // Whether the time series is due a row at this cycle of the current stage.
  bool row_due(std::uint64_t cycle) const { return (cycle - stage_start_) % output_interval_ == 0; }

  std::uint64_t done(const WorldSession& world) const { return world.cycle_count() - start_cycle_; }
  // The length or cap of every stage run, added up: what `done` reaches at most.
  std::uint64_t total() const { return total_; }

  // The world's health, assessed `always` at the end of a stage, otherwise
  // at a pace that costs at most about 5% of the run's time; each healthy
  // state is kept, so a failure has a recent good state to write, whatever
  // the case's size.
  HealthWatch& health() { return health_; }
  const StateCheckpoint& last_good() const { return health_.last_good(); }

  void stop(std::string reason);
  void fail(std::string error);
  void complete();
  bool ending() const { return outcome_ == ProgrammeOutcome::kStopped || outcome_ == ProgrammeOutcome::kFailed; }
  ProgrammeOutcome outcome() const { return outcome_; }
  const std::string& reason() const { return reason_; }  // why it stopped or failed

 private:
  std::size_t stage_count_;
  std::uint64_t output_interval_;
  std::uint64_t start_cycle_;
  std::uint64_t total_ = 0;
  std::size_t stage_ = 0;
  std::uint64_t stage_start_;
  HealthWatch health_;
  ProgrammeOutcome outcome_ = ProgrammeOutcome::kRunning;
  std::string reason_;
};

}  // namespace dem::service
