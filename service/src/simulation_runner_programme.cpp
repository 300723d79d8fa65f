// The engine thread running a case's stages: in one-shot mode (dem_server
// --case FILE --run-and-exit) and for the run_programme command -
// SimulationRunner::run_programme and what it calls. The stages are the
// case's as io converted them (CaseProgramme), each a stage of the
// engine's (StageRunT) that the command loop (serve(), in
// simulation_runner.cpp) steps chunk by chunk as it steps a cycle command,
// answering the commands that arrive between chunks.
#include <spdlog/spdlog.h>

#include <cmath>

#include "dem/io/snapshot_file.h"
#include "dem/service/command_error.h"
#include "dem/service/simulation_runner.h"

namespace dem::service {

using protocol::ReplyStatus;
using protocol::ServerState;

void SimulationRunner::run_programme() {
  const std::size_t stages = simulation_.programme().stage_count();  // the initial case: Server requires one
  if (resumed_) {
    const io::ResumePoint point = *std::exchange(resumed_, std::nullopt);
    if (point.stage >= stages) return;
    start_programme(point.stage, stages - point.stage, point.stage_cycles);
  } else {
    start_programme(0, stages);
    record_programme_row();  // the series start where the programme does, as dem_run's
  }
  serve(true);
}

void SimulationRunner::run_programme(ReceivedCommand& received) {
  const protocol::ProgrammeArgs& args = received.command.programme;
  const std::size_t stages = simulation_.programme().stage_count();
  if (stages == 0) {
    throw CommandError(ReplyStatus::kRefused, "run_programme refused: " + simulation_.case_name() +
                                                  " has no stages (a snapshot keeps none; load the case)");
  }
  const std::size_t first = args.first_stage == 0 ? 0 : args.first_stage - 1;
  if (first >= stages) {
    throw CommandError(ReplyStatus::kBadRequest, "first_stage " + std::to_string(args.first_stage) + " is past the " +
                                                     std::to_string(stages) + " stages of " + simulation_.case_name());
  }
  if (args.stage_count > stages - first) {
    throw CommandError(ReplyStatus::kBadRequest, std::to_string(args.stage_count) + " stages from stage " +
                                                     std::to_string(first + 1) + " go past the " +
                                                     std::to_string(stages) + " of " + simulation_.case_name());
  }
  start_programme(first, args.stage_count == 0 ? stages - first : args.stage_count);
  record_programme_row();
  programme_command_ = std::move(received);  // its one reply comes when the programme ends
  owner_left_logged_ = false;
}

void SimulationRunner::start_programme(std::size_t first, std::size_t count, std::uint64_t first_done) {
  programme_.emplace(simulation_.programme(), simulation_.world(), simulation_.output_interval(), first, count,
                     first_done);
  checkpoints_.begin_programme(simulation_.world().cycle_count());
  lifecycle_.take(Transition::kStartRun);
  message_ = "programme of " + std::to_string(count) + " stages running";
  spdlog::info("running the programme of {}: stages {} to {}, up to {} cycles", simulation_.case_name(), first + 1,
               first + count, programme_->total());
}

// Between the commands: a chunk of the stage running, or the next stage
// begun, or the programme ended. Whatever the engine throws fails it.
void SimulationRunner::step_programme() {
  ProgrammeRun& programme = *programme_;
  if (queue_.shutdown_requested()) programme.stop("the server is shutting down");
  try {
    if (!programme.ending()) {
      programme_chunk();
    } else if (programme.outcome() == ProgrammeOutcome::kStopped && programme.stage_running() &&
               !programme_unhealthy(true)) {
      end_stage();  // stopped: the stage ends where it is, when that is a good state
    }
  } catch (const std::exception& error) {
    programme.fail("the engine failed at cycle " + std::to_string(simulation_.world().cycle_count()) + " in " +
                   stage_label(programme.stage()) + ": " + failure_reason(error));
  }
  if (programme.outcome() != ProgrammeOutcome::kRunning) end_programme();
}

// A row of the time series at the case's interval, telemetry on schedule,
// and the stage's condition check, as the engine's run_stage orders them
// (the row before the check at the same cycle). The health check comes
// first, so nothing is recorded or kept of a broken state.
void SimulationRunner::programme_chunk() {
  ProgrammeRun& programme = *programme_;
  WorldSession& world = simulation_.world();
  if (!programme.stage_running()) {
    const std::uint64_t done = programme.next_stage(world);
    message_ = stage_label(programme.stage()) + " running";
    announce();
    programme.run(simulation_.programme().begin_stage(programme.stage(), world, done));
  }
  StageStepper& stage = programme.stepper();
  const std::uint64_t cycles =
      chunk_cycles(std::min(stage.cycles_to_next_stop(), programme.cycles_to_row(world.cycle_count())));
  timed(cycles, [&] { stage.cycle(cycles); });
  if (programme_unhealthy(false)) return;
  if (programme.row_due(world.cycle_count())) {
    record_programme_row();
    if (programme.ending()) return;
    const std::uint64_t stage_cycles = programme.stage_cycles(world.cycle_count());
    if (checkpoints_.due(world.cycle_count()) &&
        simulation_.programme().resumable_at(programme.stage(), stage_cycles, world)) {
      if (programme_unhealthy(true)) return;  // only a healthy state is kept
      write_checkpoint(programme.stage(), stage_cycles);
    }
  }
  if (schedule_.due(world.cycle_count(), world.time())) publish_telemetry();
  if (!stage.check()) {
    refresh_cache();
    return;
  }
  if (programme_unhealthy(true)) return;
  end_stage();
  if (!programme.ending() && !programme.stages_left()) programme.complete();
}

bool SimulationRunner::programme_unhealthy(bool always) {
  // A blow-up's motion (not finite, a particle flung out) is looked for at
  // every call: it is what a blow-up reaches between two paced assessments.
  WorldSession& world = simulation_.world();
  const bool suspect = world.motion_suspect();
  const std::optional<StepHealth> problem = programme_->health().check(world, always || suspect);
  if (!problem) return false;
  programme_->fail("the run is unhealthy in " + stage_label(programme_->stage()) + " " + problem->message);
  return true;
}

void SimulationRunner::record_programme_row() {
  recorder_.record(simulation_.world().view(), programme_->stage());
  if (recorder_.failed()) programme_->fail("an output file could not be written (see the error above)");
}

void SimulationRunner::end_stage() {
  const WorldSession& world = simulation_.world();
  const std::size_t stage = programme_->stage();
  const StageResult result = programme_->end_stage();
  record_programme_row();
  recorder_.record_stage(stage, simulation_.programme().stage_name(stage), result, world.cycle_count(), world.time());
  if (recorder_.failed()) programme_->fail("an output file could not be written (see the error above)");
  // The state a stage ends in - its stop condition met, the last of a
  // programme's - is telemetry whatever the schedule: monitors, dashboards
  // and recordings end where the run does.
  if (world.cycle_count() != last_telemetry_cycle_ || !telemetry_published_) publish_telemetry(false);
  spdlog::info("{}: {} cycles{}, to cycle {}", stage_label(stage), result.cycles_run,
               result.condition_met ? ", its stop condition met" : "", world.cycle_count());
}

// The final snapshot beside the tables: the state reached, or after a
// failure the last state known to be good (the one at the failure is not);
// then the run_programme command's reply.
void SimulationRunner::end_programme() {
  WorldSession& world = simulation_.world();
  ProgrammeRun& programme = *programme_;
  programme.mark_over();
  const bool failed = programme.outcome() == ProgrammeOutcome::kFailed;
  const std::string name = failed ? "last_good.snapshot" : "final.snapshot";
  const std::filesystem::path path = recorder_.case_directory() / name;
  bool written = true;
  try {
    io::write_snapshot_bytes(recorder_.own_file(name), failed ? programme.last_good().bytes(simulation_.snapshot_info())
                                                              : simulation_.snapshot_bytes());
  } catch (const std::exception& error) {
    written = false;
    spdlog::error("the snapshot cannot be written: {}", error.what());
    programme.fail("the snapshot cannot be written: " + std::string(error.what()));
  }
  const std::string at = " at cycle " + std::to_string(world.cycle_count());
  const std::uint64_t cycles_run = programme.done(world);
  switch (programme.outcome()) {
    case ProgrammeOutcome::kCompleted:
      lifecycle_.take(Transition::kEndRun);
      message_ = "programme complete" + at + "; final snapshot " + path.string();
      spdlog::info("{}", message_);
      break;
    case ProgrammeOutcome::kStopped:
      lifecycle_.take(Transition::kEndRun);
      message_ = "programme stopped" + at + " in " + stage_label(programme.stage()) + " (" + programme.reason() +
                 "); final snapshot " + path.string();
      spdlog::warn("{}", message_);
      break;
    case ProgrammeOutcome::kFailed:
    case ProgrammeOutcome::kRunning:
      lifecycle_.take(Transition::kFailRun);
      message_ = "programme failed: " + programme.reason();
      if (failed) {
        // The world goes back to it: what the server shows and saves from now on is sound.
        message_ += "; " + go_back_to(programme.last_good());
        if (written && !world_lost_) message_ += ", which is in " + path.string();
      }
      spdlog::error("{}", message_);
      break;
  }
  drop_lost_world();
  if (!programme_command_) {
    publish_status();  // the one-shot mode: the server ends with it
    return;
  }
  protocol::Reply reply;
  reply.cycles_run = cycles_run;
  reply.message = message_;
  reply.status = programme.outcome() == ProgrammeOutcome::kCompleted ? ReplyStatus::kOk
                 : programme.outcome() == ProgrammeOutcome::kStopped ? ReplyStatus::kCancelled
                                                                     : ReplyStatus::kFailed;
  const ReceivedCommand received = *std::exchange(programme_command_, std::nullopt);
  programme_.reset();  // cycle and run_until record the tables at the telemetry interval again
  checkpoints_.end_programme(world.cycle_count());
  announce();  // before the reply: who reads it sees the programme ended
  send(received, std::move(reply));
}

std::string SimulationRunner::stage_label(std::size_t stage) const {
  if (stage >= programme_->stage_count()) return "the end of the programme";
  const std::string& name = simulation_.programme().stage_name(stage);
  return "stage " + std::to_string(stage + 1) + "/" + std::to_string(programme_->stage_count()) +
         (name.empty() ? std::string() : " " + name);
}

std::optional<ProgrammeOutcome> SimulationRunner::programme_outcome() const {
  if (!programme_) return std::nullopt;
  return programme_->outcome();
}

}  // namespace dem::service
