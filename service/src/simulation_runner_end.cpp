// The one end of every run (a cycle, run_until or programme): after a
// failure the last good state written beside the tables and the world put
// back at it; the case's final snapshot; the state, the message and the
// reply to the command that started the run. And what fails a run from
// outside its chunk.
#include <spdlog/spdlog.h>

#include "dem/io/snapshot_file.h"
#include "dem/service/command_error.h"
#include "dem/service/simulation_runner.h"

namespace dem::service {

using protocol::ReplyStatus;

void SimulationRunner::end_run() {
  ProgrammeRun& run = *run_;
  run.mark_over();
  const std::uint64_t cycles_run = run.done(simulation_.world());  // before a failed run's world goes back
  const RunPosition position = run.position(simulation_.world().cycle_count());
  if (run.outcome() == ProgrammeOutcome::kFailed) {
    message_ = failure_message();
  } else if (run.outcome() == ProgrammeOutcome::kPaused) {
    message_ = pause_message(position);
  } else if (run.of_case()) {
    message_ = programme_end_message();  // which fails the run when its snapshot cannot be written
  } else {
    message_ = command_end_message(cycles_run);
  }
  const ProgrammeOutcome outcome = run.outcome();
  lifecycle_.take(outcome == ProgrammeOutcome::kFailed ? Transition::kFailRun : Transition::kEndRun);
  const auto level = outcome == ProgrammeOutcome::kStopped  ? spdlog::level::warn
                     : outcome == ProgrammeOutcome::kFailed ? spdlog::level::err
                                                            : spdlog::level::info;
  // A command's end is in its reply's log line; a failure is said here too,
  // and a programme's end unless it merely paused at a sample.
  if ((run.of_case() && outcome != ProgrammeOutcome::kPaused) || outcome == ProgrammeOutcome::kFailed) {
    spdlog::log(level, "{}", message_);
  }
  drop_lost_world();
  if (!run.command()) {
    publish_status();  // the one-shot mode: the server ends with it
    return;
  }
  protocol::Reply reply = run_reply(outcome, cycles_run, position);
  const ReceivedCommand received = *run.command();
  if (run.of_case()) checkpoints_.end_programme(simulation_.loaded() ? simulation_.world().cycle_count() : 0);
  run_.reset();  // cycle and run_until record the tables at the telemetry interval again
  announce();    // before the reply: who reads it sees the run ended
  send(received, std::move(reply));
}

protocol::Reply SimulationRunner::run_reply(ProgrammeOutcome outcome, std::uint64_t cycles_run,
                                            const RunPosition& position) const {
  protocol::Reply reply;
  reply.status = outcome == ProgrammeOutcome::kStopped  ? ReplyStatus::kCancelled
                 : outcome == ProgrammeOutcome::kFailed ? ReplyStatus::kFailed
                                                        : ReplyStatus::kOk;
  reply.message = message_;
  reply.cycles_run = cycles_run;
  reply.condition_met = run_->last_result().condition_met;
  if (run_->of_case()) {
    reply.stage = static_cast<std::uint32_t>(position.stage + 1);
    reply.stage_cycles = position.stage_cycles;
    reply.stage_ended = position.stage_ended;
  }
  return reply;
}

std::string SimulationRunner::pause_message(const RunPosition& position) const {
  return "programme paused at cycle " + std::to_string(simulation_.world().cycle_count()) + ", " +
         std::to_string(position.stage_cycles) + " cycles into " + stage_label(position.stage) +
         (position.stage_ended ? ", which ended there" : "");
}

// The state at a failure is not good: the last one known to be is written
// beside the tables, and the world goes back to it, so what the server
// shows and saves from now on is sound.
std::string SimulationRunner::failure_message() {
  const ProgrammeRun& run = *run_;
  const std::optional<std::string> not_written =
      write_beside_tables("last_good.snapshot", [&] { return run.last_good().bytes(simulation_.snapshot_info()); });
  std::string message = (run.of_case() ? "programme failed: " : "") + run.reason() + "; " + go_back_to(run.last_good());
  if (world_lost_) return message;
  if (not_written) return message + " (it could not be written: " + *not_written + ")";
  return message + ", which is in " + (recorder_.case_directory() / "last_good.snapshot").string();
}

std::string SimulationRunner::programme_end_message() {
  ProgrammeRun& run = *run_;
  if (const auto not_written = write_beside_tables("final.snapshot", [&] { return simulation_.snapshot_bytes(); })) {
    run.fail("the snapshot cannot be written: " + *not_written);
    return "programme failed: " + run.reason();
  }
  const std::string at = " at cycle " + std::to_string(simulation_.world().cycle_count());
  const std::string snapshot = "; final snapshot " + (recorder_.case_directory() / "final.snapshot").string();
  if (run.outcome() == ProgrammeOutcome::kCompleted) return "programme complete" + at + snapshot;
  return "programme stopped" + at + " in " + stage_label(run.stage()) + " (" + run.reason() + ")" + snapshot;
}

std::string SimulationRunner::command_end_message(std::uint64_t cycles_run) const {
  const ProgrammeRun& run = *run_;
  if (run.outcome() == ProgrammeOutcome::kStopped) return run.reason();
  const std::string cycles = std::to_string(cycles_run) + " cycles";
  if (run.last_result().condition_met) {
    return conditions_reached(run.programme().stage_until(0), simulation_.world()) + " after " + cycles;
  }
  return "ran " + cycles + " to cycle " + std::to_string(simulation_.world().cycle_count());
}

std::optional<std::string> SimulationRunner::write_beside_tables(const std::string& name,
                                                                 const std::function<std::string()>& bytes) {
  try {
    io::write_snapshot_bytes(recorder_.own_file(name), bytes());
    return std::nullopt;
  } catch (const std::exception& error) {
    spdlog::error("{} cannot be written: {}", name, error.what());
    return std::string(error.what());
  }
}

std::string SimulationRunner::go_back_to(const StateCheckpoint& good) {
  try {
    good.restore(simulation_.world());
    ++world_generation_;
    return "the world is back at the last good state, cycle " + std::to_string(good.cycle());
  } catch (const std::exception& error) {
    // The session has no world left (WorldSession::restore): nothing reads it from here on.
    world_lost_ = true;
    simulation_.drop();
    readout_.reset();
    ++world_generation_;
    return "the world could not be put back at its last good state (" + failure_reason(error) +
           ") and is let go: load a case or a snapshot";
  }
}

void SimulationRunner::drop_lost_world() {
  if (!world_lost_) return;
  world_lost_ = false;
  lifecycle_.take(Transition::kLoseWorld);
  announce();
}

void SimulationRunner::fail_anything_running(const std::exception& error) {
  spdlog::error("the engine thread ran into: {}", failure_reason(error));
  if (!run_going()) return;
  const std::string at = simulation_.loaded() ? std::to_string(simulation_.world().cycle_count()) : "?";
  run_->fail("the run failed at cycle " + at + in_stage() + ": " + failure_reason(error));
  end_run();
}

}  // namespace dem::service
