// The one run driver: every run - a cycle or run_until command (a stage of
// its own), a run_programme command, the one-shot mode (the case's stages)
// - is a ProgrammeRun whose stages, each a stage of the engine's
// (StageRunT), the command loop (serve(), in simulation_runner.cpp) steps
// a chunk at a time, answering the commands that arrive between chunks.
// Its end is in simulation_runner_end.cpp.
#include <spdlog/spdlog.h>

#include "dem/service/command_error.h"
#include "dem/service/simulation_runner.h"

namespace dem::service {

// Between the commands: a chunk of the stage running (or the next stage
// begun), or the run ended. Whatever the engine throws fails it; the end
// puts the world back at its last good state (the step may have stopped
// half-way: memory ran out in it).
void SimulationRunner::step_run() {
  ProgrammeRun& run = *run_;
  if (queue_.shutdown_requested()) run.stop("the server is shutting down");
  try {
    if (!run.ending()) {
      run_chunk();
    } else if (run.outcome() == ProgrammeOutcome::kStopped && run.stage_running() && !run_unhealthy(true)) {
      end_stage();  // stopped: the stage ends where it is, when that is a good state
    }
  } catch (const std::exception& error) {
    run.fail("the run failed at cycle " + std::to_string(simulation_.world().cycle_count()) + in_stage() + ": " +
             failure_reason(error));
  }
  if (run.outcome() != ProgrammeOutcome::kRunning) end_run();
}

// A row of the time series at the case's interval, telemetry on schedule,
// and the stage's condition check, as the engine's run_stage orders them
// (the row before the check at the same cycle); a checkpoint where the run
// goes on. The health check comes first, so nothing is recorded or kept of
// a broken state: a blow-up's motion (not finite, a particle flung out) is
// looked for after every chunk, as it is what a blow-up reaches between
// two paced assessments.
void SimulationRunner::run_chunk() {
  ProgrammeRun& run = *run_;
  WorldSession& world = simulation_.world();
  if (!run.stage_running()) {
    run.begin_next_stage(world);
    if (run.of_case()) {
      message_ = stage_label(run.stage()) + " running";
      announce();
    }
  }
  StageStepper& stage = run.stepper();
  const std::uint64_t cycles = chunk_cycles(run.cycles_to_next_stop(world.cycle_count()));
  timed(cycles, [&] { stage.cycle(cycles); });
  if (run_unhealthy(false)) return;
  if (run.row_due(world.cycle_count())) {
    record_row();
    if (run.ending()) return;
  }
  if (schedule_.due(world.cycle_count(), world.time())) publish_telemetry();
  if (!stage.check()) {
    if (run.sample_due(world.cycle_count())) return pause_run();
    checkpoint_if_due();
    refresh_cache();
    return;
  }
  if (run_unhealthy(true)) return;
  end_stage();
  if (run.ending()) return;
  if (!run.stages_left()) {
    run.complete();
  } else if (run.pauses()) {
    run.pause();  // its client learns each stage's result
  }
}

// A sample point: the run returns with the world as it is here, for its
// client to read, and a run_programme that resumes it goes on as if never
// interrupted. Only a healthy state is handed over.
void SimulationRunner::pause_run() {
  if (run_unhealthy(true)) return;
  run_->pause();
}

bool SimulationRunner::run_unhealthy(bool always) {
  WorldSession& world = simulation_.world();
  const bool suspect = world.motion_suspect();
  const std::optional<StepHealth> problem = run_->health().check(world, always || suspect);
  if (!problem) return false;
  run_->fail("the run is unhealthy" + in_stage() + " " + problem->message);
  return true;
}

// Only a state found healthy is kept; of the case's stages only at a row
// where the stage can be resumed as if never interrupted (on one of its
// checks, its conditions not holding).
void SimulationRunner::checkpoint_if_due() {
  const ProgrammeRun& run = *run_;
  const WorldSession& world = simulation_.world();
  const std::uint64_t cycle = world.cycle_count();
  if (!checkpoints_.due(cycle)) return;
  const std::uint64_t stage_cycles = run.stage_cycles(cycle);
  if (run.of_case() && !(run.row_due(cycle) && run.programme().resumable_at(run.stage(), stage_cycles, world))) {
    return;
  }
  if (run_unhealthy(true)) return;
  // A command's checkpoint is of the world alone: --resume continues the case's programme.
  write_checkpoint(run.of_case() ? run.stage() : 0, run.of_case() ? stage_cycles : 0);
}

void SimulationRunner::record_row() {
  recorder_.record(simulation_.world(), run_->stage());
  if (recorder_.failed()) run_->fail("an output file could not be written (see the error above)");
}

// The state a stage ends in - its stop condition met, the last of a run's
// - is telemetry whatever the schedule: monitors, dashboards and
// recordings end where the run does. The case's stages add their row and
// their record to the tables.
void SimulationRunner::end_stage() {
  const WorldSession& world = simulation_.world();
  ProgrammeRun& run = *run_;
  const std::size_t stage = run.stage();
  const StageResult result = run.end_stage();
  if (run.of_case()) {
    record_row();
    recorder_.record_stage(stage, run.programme().stage_name(stage), result, world.cycle_count(), world.time());
    if (recorder_.failed()) run.fail("an output file could not be written (see the error above)");
    spdlog::info("{}: {} cycles{}, to cycle {}", stage_label(stage), result.cycles_run,
                 result.condition_met ? ", its stop condition met" : "", world.cycle_count());
  }
  if (world.cycle_count() != last_telemetry_cycle_ || !telemetry_published_) publish_telemetry(false);
}

std::string SimulationRunner::stage_label(std::size_t stage) const {
  if (stage >= run_->stage_count()) return "the end of the programme";
  const std::string& name = run_->programme().stage_name(stage);
  return "stage " + std::to_string(stage + 1) + "/" + std::to_string(run_->stage_count()) +
         (name.empty() ? std::string() : " " + name);
}

std::string SimulationRunner::in_stage() const { return run_->of_case() ? " in " + stage_label(run_->stage()) : ""; }

std::optional<ProgrammeOutcome> SimulationRunner::programme_outcome() const {
  if (!run_) return std::nullopt;
  return run_->outcome();
}

}  // namespace dem::service
