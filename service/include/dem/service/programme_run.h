// A case's loading programme as the server runs it (dem_server --case FILE
// --run-and-exit, or the run_programme command): which stage is running,
// its steps (the engine's stage runner, begun by CaseProgramme), when the
// time series is due a row, the last state known to be good, and how the
// programme ended. The runner steps the stage chunk by chunk from its
// command loop; the engine's StageRunT decides each stage's end. This is
// only the bookkeeping around it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "dem/service/case_programme.h"
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
  // the stages run are first .. first + count - 1 (from 0), the first of
  // them `first_done` cycles in already (a resumed checkpoint's).
  ProgrammeRun(const CaseProgramme& programme, const WorldSession& world, std::uint64_t output_interval,
               std::size_t first, std::size_t count, std::uint64_t first_done = 0);

  std::size_t stage_count() const { return stage_count_; }  // the case's
  std::size_t stage() const { return stage_; }  // the stage running or last run, or stage_count() after the last

  // Between stages: whether one is left to run.
  bool stage_running() const { return stepper_ != nullptr; }
  bool stages_left() const { return next_ < end_; }
  // Moves on to the next stage (stage() from now on), counted from
  // where `world` is, less the cycles of it run already; returns those.
  std::uint64_t next_stage(const WorldSession& world);
  // The running stage's steps, begun by CaseProgramme::begin_stage.
  void run(std::unique_ptr<StageStepper> stepper) { stepper_ = std::move(stepper); }
  StageStepper& stepper() { return *stepper_; }
  // The running stage is over (or cut short); what it ran, counting the
  // cycles of it run before a resume.
  StageResult end_stage();

  std::uint64_t stage_cycles(std::uint64_t cycle) const { return cycle - stage_start_; }
  // Whether the time series is due a row at this cycle of the current
  // stage, and the cycles to the next such row.
  bool row_due(std::uint64_t cycle) const { return (cycle - stage_start_) % output_interval_ == 0; }
  std::uint64_t cycles_to_row(std::uint64_t cycle) const {
    return output_interval_ - (cycle - stage_start_) % output_interval_;
  }

  // The share of the programme done, the running stage `stage_fraction` of
  // the way (CaseProgramme::progress): each stage run counts alike, as
  // their lengths are not known before they end.
  double progress(double stage_fraction) const;

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
  // Its end is done (the final snapshot, the state): nothing runs any more.
  void mark_over() { over_ = true; }
  bool over() const { return over_; }
  const std::string& reason() const { return reason_; }  // why it stopped or failed

 private:
  std::size_t stage_count_;
  std::uint64_t output_interval_;
  std::uint64_t start_cycle_;
  std::uint64_t total_ = 0;
  std::size_t first_;
  std::size_t next_;
  std::size_t end_;
  std::uint64_t first_done_;
  std::size_t stage_;
  std::uint64_t stage_start_;
  std::uint64_t stage_done_ = 0;  // the running stage's cycles before a resume
  std::unique_ptr<StageStepper> stepper_;
  HealthWatch health_;
  ProgrammeOutcome outcome_ = ProgrammeOutcome::kRunning;
  bool over_ = false;
  std::string reason_;
};

}  // namespace dem::service
