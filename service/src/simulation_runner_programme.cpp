// The engine thread running a case's stages: in one-shot mode (dem_server
// --case FILE --run-and-exit) and for the run_programme command -
// SimulationRunner::run_programme and what it calls. The stages are the
// case's as io converted them, each run by the engine's run_stage (through
// WorldSession); between cycles the runner does what it does between the
// chunks of a cycle command. The command loop is in simulation_runner.cpp.
#include <spdlog/spdlog.h>

#include <cmath>

#include "dem/io/snapshot_file.h"
#include "dem/service/command_error.h"
#include "dem/service/simulation_runner.h"

namespace dem::service {

using protocol::ReplyStatus;
using protocol::ServerState;

void SimulationRunner::run_programme() {
  const std::size_t stages = simulation_.world().stage_count();  // the initial case: Server requires one
  if (resumed_) {
    const io::ResumePoint point = *std::exchange(resumed_, std::nullopt);
    if (point.stage < stages) run_stages(point.stage, stages - point.stage, point.stage_cycles);
    return;
  }
  run_stages(0, stages);
}

void SimulationRunner::run_programme(const ReceivedCommand& received) {
  const protocol::ProgrammeArgs& args = received.command.programme;
  const std::size_t stages = simulation_.world().stage_count();
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
  const std::uint64_t start = simulation_.world().cycle_count();
  programme_command_ = &received;
  owner_left_logged_ = false;
  run_stages(first, args.stage_count == 0 ? stages - first : args.stage_count);
  programme_command_ = nullptr;
  protocol::Reply reply;
  reply.cycles_run = simulation_.world().cycle_count() - start;
  reply.message = message_;
  switch (programme_->outcome()) {
    case ProgrammeOutcome::kCompleted:
      reply.status = ReplyStatus::kOk;
      break;
    case ProgrammeOutcome::kStopped:
      reply.status = ReplyStatus::kCancelled;
      break;
    default:
      reply.status = ReplyStatus::kFailed;
      break;
  }
  programme_.reset();  // cycle and run_until record the tables at the telemetry interval again
  announce();          // before the reply: who reads it sees the programme ended
  send(received, std::move(reply));
}

// Stages first .. first + count - 1 (from 0), each by the engine's run_stage.
void SimulationRunner::run_stages(std::size_t first, std::size_t count, std::uint64_t first_done) {
  WorldSession& world = simulation_.world();
  programme_.emplace(world, simulation_.output_interval(), first, count);
  lifecycle_.take(Transition::kStartRun);
  message_ = "programme of " + std::to_string(count) + " stages running";
  spdlog::info("running the programme of {}: stages {} to {}, up to {} cycles", simulation_.case_name(), first + 1,
               first + count, programme_->total());
  last_poll_ = std::chrono::steady_clock::now();
  for (std::size_t i = first; i < first + count && !programme_->ending(); ++i) {
    if (queue_.shutdown_requested()) {
      programme_->stop("the server is shutting down");
      break;
    }
    const std::uint64_t done = i == first ? first_done : 0;
    programme_->start_stage(i, world, done);
    message_ = stage_label(i) + " running";
    announce();
    StageResult result;
    try {
      result = world.run_stage(
          i, [this] { return between_programme_cycles(); }, done);
    } catch (const std::exception& error) {
      programme_->fail("the engine failed at cycle " + std::to_string(world.cycle_count()) + " in " + stage_label(i) +
                       ": " + error.what());
      break;
    }
    if (programme_->outcome() == ProgrammeOutcome::kFailed || programme_unhealthy(true)) break;
    end_stage(i, result);
  }
  if (!programme_->ending()) programme_->complete();
  end_programme();
}

// After every cycle of a stage: a row of the time series at the case's
// interval, telemetry on schedule, and every chunk_duration the commands
// that came in, as run_chunk does between its chunks. The health check
// comes first at both, so nothing is recorded or kept of a broken state.
bool SimulationRunner::between_programme_cycles() {
  const WorldSession& world = simulation_.world();
  const auto now = std::chrono::steady_clock::now();
  const bool row = programme_->row_due(world.cycle_count());
  const bool poll = now - last_poll_ >= options_.chunk_duration;
  if ((row || poll) && programme_unhealthy(false)) return false;
  if (row) {
    record_programme_row();
    const std::size_t stage = programme_->stage();
    const std::uint64_t stage_cycles = programme_->stage_cycles(world.cycle_count());
    if (checkpoints_.due(world.cycle_count()) && world.resumable_at(stage, stage_cycles)) {
      if (programme_unhealthy(true)) return false;  // only a healthy state is kept
      write_checkpoint(stage, stage_cycles);
    }
  }
  if (schedule_.due(world.cycle_count(), world.time())) publish_telemetry();
  if (poll) {
    last_poll_ = now;
    for (ReceivedCommand& received : queue_.take_all()) {
      if (queue_.shutdown_requested()) {
        unanswered_.push_back(std::move(received));
      } else {
        execute(std::move(received));
      }
    }
    if (queue_.shutdown_requested()) programme_->stop("the server is shutting down");
    if (now - last_status_ >= options_.progress_interval) {
      note_owner_left();
      publish_status();
    }
    refresh_cache();
  }
  return !programme_->ending();
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
  simulation_.world().record_tables(recorder_, programme_->stage());
  if (recorder_.failed()) programme_->fail("an output file could not be written (see the error above)");
}

void SimulationRunner::end_stage(std::size_t stage, const StageResult& result) {
  const WorldSession& world = simulation_.world();
  record_programme_row();
  recorder_.record_stage(stage, world.stage_name(stage), result, world.cycle_count(), world.time());
  if (recorder_.failed()) programme_->fail("an output file could not be written (see the error above)");
  spdlog::info("{}: {} cycles{}, to cycle {}", stage_label(stage), result.cycles_run,
               result.condition_met ? ", its stop condition met" : "", world.cycle_count());
}

// The final snapshot beside the tables: the state reached, or after a
// failure the last state known to be good (the one at the failure is not).
void SimulationRunner::end_programme() {
  const WorldSession& world = simulation_.world();
  const bool failed = programme_->outcome() == ProgrammeOutcome::kFailed;
  const std::string name = failed ? "last_good.snapshot" : "final.snapshot";
  const std::filesystem::path path = recorder_.case_directory() / name;
  const std::uint64_t snapshot_cycle = failed ? programme_->last_good().cycle() : world.cycle_count();
  bool written = true;
  try {
    io::write_snapshot_bytes(recorder_.own_file(name), failed
                                                           ? programme_->last_good().bytes(simulation_.snapshot_info())
                                                           : simulation_.snapshot_bytes());
  } catch (const std::exception& error) {
    written = false;
    spdlog::error("the snapshot cannot be written: {}", error.what());
    programme_->fail("the snapshot cannot be written: " + std::string(error.what()));
  }
  const std::string at = " at cycle " + std::to_string(world.cycle_count());
  switch (programme_->outcome()) {
    case ProgrammeOutcome::kCompleted:
      lifecycle_.take(Transition::kEndRun);
      message_ = "programme complete" + at + "; final snapshot " + path.string();
      spdlog::info("{}", message_);
      break;
    case ProgrammeOutcome::kStopped:
      lifecycle_.take(Transition::kEndRun);
      message_ = "programme stopped" + at + " in " + stage_label(programme_->stage()) + " (" + programme_->reason() +
                 "); final snapshot " + path.string();
      spdlog::warn("{}", message_);
      break;
    case ProgrammeOutcome::kFailed:
    case ProgrammeOutcome::kRunning:
      lifecycle_.take(Transition::kFailRun);
      message_ = "programme failed: " + programme_->reason();
      if (failed) {
        // The world goes back to it: what the server shows and saves from now on is sound.
        simulation_.world().restore(programme_->last_good());
        ++world_generation_;
        message_ += "; the world is back at the last good state, cycle " + std::to_string(snapshot_cycle);
        if (written) message_ += ", which is in " + path.string();
      }
      spdlog::error("{}", message_);
      break;
  }
  publish_status();
}

std::string SimulationRunner::stage_label(std::size_t stage) const {
  if (stage >= programme_->stage_count()) return "the end of the programme";
  const std::string& name = simulation_.world().stage_name(stage);
  return "stage " + std::to_string(stage + 1) + "/" + std::to_string(programme_->stage_count()) +
         (name.empty() ? std::string() : " " + name);
}

std::optional<ProgrammeOutcome> SimulationRunner::programme_outcome() const {
  if (!programme_) return std::nullopt;
  return programme_->outcome();
}

}  // namespace dem::service
