// A run as the server drives it, whatever started it: a cycle or run_until
// command (a programme of one stage of its own), a run_programme command
// or the one-shot mode (dem_server --case FILE --run-and-exit: the case's
// stages). Which stage is running, its steps (the engine's stage runner,
// begun by CaseProgramme), when the time series is due a row, the last
// state known to be good, and how the run ended. The runner steps the
// stage chunk by chunk from its command loop; the engine's StageRunT
// decides each stage's end. This is only the bookkeeping around it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "dem/service/case_programme.h"
#include "dem/service/command_queue.h"
#include "dem/service/health_watch.h"
#include "dem/service/world_session.h"

namespace dem::service {

enum class ProgrammeOutcome {
  kRunning,
  kCompleted,  // every stage ran
  kStopped,    // ended early by a stop or shutdown command, SIGINT or SIGTERM
  kFailed,     // the engine failed or blew up, or an output could not be written
  kPaused,     // returned at a sample point or a stage's end (RunPlan::sample_every), to be resumed
};

// What a run runs: stages first .. first + count - 1 (from 0) of
// `programme`, the first of them `first_done` cycles in already (a resumed
// checkpoint's).
struct RunPlan {
  CaseProgramme programme;  // the case's stages, or a command's one (CaseProgramme::one_stage)
  std::size_t first = 0;
  std::size_t count = 1;
  std::uint64_t first_done = 0;
  // The case's own stages write the case's outputs as dem_run does - a row
  // of the time series every `output_interval` cycles counted from each
  // stage's start (the case's output.interval), a record per stage, the
  // final snapshot - and checkpoint by the programme's settings. A
  // command's stage leaves the tables to the telemetry's rhythm, as
  // between runs, and writes no final snapshot.
  bool of_case = false;
  std::uint64_t output_interval = 1;
  // > 0: the run returns every `sample_every` cycles of a stage, counted
  // from its start, and at each stage's end, so its client reads the world
  // at exact cycles (run_programme's programme_steps, docs/SERVICE.md).
  std::uint64_t sample_every = 0;
  bool stage_ends = false;  // the run returns at each stage's end (implied by sample_every)
};

// Where a run is, or returned: its stage (from 0), that stage's cycles run
// (counting those before a resume) and whether it is over.
struct RunPosition {
  std::size_t stage = 0;
  std::uint64_t stage_cycles = 0;
  bool stage_ended = false;
};

class ProgrammeRun {
 public:
  // Takes the world as it is now for the first good state (a whole copy:
  // memory that cannot hold it throws, with nothing started). `command`:
  // the command that started it, replied to when it ends; none in the
  // one-shot mode.
  ProgrammeRun(RunPlan plan, const WorldSession& world, std::optional<ReceivedCommand> command);

  const CaseProgramme& programme() const { return plan_.programme; }
  bool of_case() const { return plan_.of_case; }
  const ReceivedCommand* command() const { return command_ ? &*command_ : nullptr; }

  std::size_t stage_count() const { return plan_.programme.stage_count(); }
  std::size_t stage() const { return stage_; }  // the stage running or last run, or stage_count() after the last

  // Between stages: whether one is left to run.
  bool stage_running() const { return stepper_.has_value(); }
  bool stages_left() const { return next_ < plan_.first + plan_.count; }
  // Begins the next stage on `world` (stage() from now on), counted from
  // where `world` is, less the cycles of it run already. Throws what the
  // engine throws.
  void begin_next_stage(WorldSession& world);
  StageStepper& stepper() { return *stepper_; }
  // The running stage is over (or cut short); what it ran, counting the
  // cycles of it run before a resume.
  StageResult end_stage();
  // The last stage ended's result: whether its stop condition ended it.
  const StageResult& last_result() const { return last_result_; }

  std::uint64_t stage_cycles(std::uint64_t cycle) const { return cycle - stage_start_; }
  // Cycles the next chunk may run at most: to the stage's next condition
  // check or end, and for the case's stages to the next row of the time series.
  std::uint64_t cycles_to_next_stop(std::uint64_t cycle) const;
  // Whether the time series is due a row at this cycle (only the case's stages write one).
  bool row_due(std::uint64_t cycle) const { return plan_.of_case && stage_cycles(cycle) % plan_.output_interval == 0; }
  // Whether the run returns here: a sample point of the running stage.
  bool sample_due(std::uint64_t cycle) const {
    return plan_.sample_every > 0 && stage_cycles(cycle) % plan_.sample_every == 0;
  }
  // Whether the run returns at each stage's end.
  bool pauses() const { return plan_.stage_ends || plan_.sample_every > 0; }
  RunPosition position(std::uint64_t cycle) const;

  // The share of the run done, the running stage `stage_fraction` of the
  // way (CaseProgramme::progress): each stage run counts alike, as their
  // lengths are not known before they end.
  double progress(double stage_fraction) const;

  std::uint64_t done(const WorldSession& world) const { return world.cycle_count() - start_cycle_; }
  // The length or cap of every stage run, added up: what `done` reaches at most.
  std::uint64_t total() const { return total_; }

  // The world's health, assessed `always` at the end of a stage, otherwise
  // at a pace that costs at most about 1% of the run's time; each healthy
  // state is kept, so a failure has a recent good state to write, whatever
  // the case's size.
  HealthWatch& health() { return health_; }
  const StateCheckpoint& last_good() const { return health_.last_good(); }

  void stop(std::string reason);
  void fail(std::string error);
  void complete();
  void pause();
  bool ending() const { return outcome_ == ProgrammeOutcome::kStopped || outcome_ == ProgrammeOutcome::kFailed; }
  ProgrammeOutcome outcome() const { return outcome_; }
  // Its end is done (the snapshot, the state, the reply): nothing runs any more.
  void mark_over() { over_ = true; }
  bool over() const { return over_; }
  const std::string& reason() const { return reason_; }  // why it stopped or failed

 private:
  RunPlan plan_;
  std::optional<ReceivedCommand> command_;
  std::uint64_t start_cycle_;
  std::uint64_t total_ = 0;
  std::size_t next_;
  std::size_t stage_;
  std::uint64_t stage_start_;
  std::uint64_t stage_done_ = 0;  // the running stage's cycles before a resume
  std::optional<StageStepper> stepper_;
  StageResult last_result_;
  std::size_t last_stage_ = 0;  // the stage last_result_ is of
  HealthWatch health_;
  ProgrammeOutcome outcome_ = ProgrammeOutcome::kRunning;
  bool over_ = false;
  std::string reason_;
};

}  // namespace dem::service
