// The engine thread's cycle and run_until commands: started, stepped chunk
// by chunk between the commands that arrive (run() in
// simulation_runner.cpp), ended, stopped or failed; who may stop them; and
// the periodic checkpoints. run_programme's stages are in
// simulation_runner_programme.cpp.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

#include "dem/io/snapshot_file.h"
#include "dem/service/command_error.h"
#include "dem/service/simulation_runner.h"

namespace dem::service {

using protocol::CommandKind;
using protocol::ReplyStatus;

namespace {

constexpr std::uint64_t kMaxChunk = 1'000'000;

}  // namespace

std::string SimulationRunner::stop() {
  if (programme_ && programme_->outcome() == ProgrammeOutcome::kRunning) {
    programme_->stop("stopped by request");
    return "stopping the programme at cycle " + std::to_string(simulation_.world().cycle_count()) + " in " +
           stage_label(programme_->stage());
  }
  if (!active_) return "nothing was running";
  const std::string what = std::string(protocol::to_string(*protocol::command_kind(active_->command().command.kind)));
  const std::uint64_t done = active_->done();
  end_run(ReplyStatus::kCancelled, "stopped by request");
  return "stopped " + what + " at cycle " + std::to_string(simulation_.world().cycle_count()) + " after " +
         std::to_string(done) + " cycles";
}

// --- who may stop a run ----------------------------------------------------

const ReceivedCommand* SimulationRunner::run_owner() const {
  if (active_) return &active_->command();
  return programme_command_ ? &*programme_command_ : nullptr;  // a one-shot programme has none: the server's own
}

// A run belongs to the client (the DDS writer) that started it. Another
// may stop it, or shut the server down under it, only with force, or once
// the owner has left the domain (then the run is orphaned: it goes on, and
// anyone may end it). Who may send commands at all is DDS Security's to
// say (its permissions), not this.
std::optional<std::string> SimulationRunner::ownership_refusal(const ReceivedCommand& received) const {
  const ReceivedCommand* owner = run_owner();
  if (owner == nullptr || owner->writer == 0 || received.writer == owner->writer) return std::nullopt;
  const std::string run = std::string(protocol::to_string(*protocol::command_kind(owner->command.kind))) +
                          " (request " + std::to_string(owner->command.request_id) + ") of client " +
                          owner->command.client_id;
  if (received.command.force) {
    spdlog::warn("{} ends the {} with force", received.command.client_id, run);
    return std::nullopt;
  }
  if (!writer_alive_(owner->writer)) {
    spdlog::info("{} ends the {}, whose client has left", received.command.client_id, run);
    return std::nullopt;
  }
  return "the running " + run +
         " belongs to that client, which is still here; send it with force to end it anyway "
         "(demctl stop --force)";
}

// Once per run, between chunks: said in the log and the status.
void SimulationRunner::note_owner_left() {
  const ReceivedCommand* owner = run_owner();
  if (owner_left_logged_ || owner == nullptr || owner->writer == 0 || writer_alive_(owner->writer)) return;
  owner_left_logged_ = true;
  spdlog::warn(
      "client {}, which started the running {}, has left the domain: the run goes on, and any client may "
      "stop it",
      owner->command.client_id, protocol::to_string(*protocol::command_kind(owner->command.kind)));
  message_ += "; its client has left";
}

// --- running commands ------------------------------------------------------

void SimulationRunner::start_run(ReceivedCommand& received, CommandKind kind) {
  const protocol::Command& command = received.command;
  RunGoal goal;
  if (kind == CommandKind::kCycle) {
    require_argument(command.cycle.cycles > 0,
                     "the cycle count must be > 0, got " + std::to_string(command.cycle.cycles));
    goal.max_cycles = static_cast<std::uint64_t>(command.cycle.cycles);
  } else {
    const protocol::RunUntilArgs& until = command.run_until;
    require_argument(until.max_cycles > 0,
                     "run_until needs a maximum cycle count > 0, got " + std::to_string(until.max_cycles));
    require_argument(until.check_interval >= 0, "the check interval must be >= 0");
    require_argument(until.stress || until.settlement || until.kinetic_energy,
                     "run_until needs a condition: a plate's stress or settlement, or the kinetic energy");
    for (const auto& value : {until.stress, until.settlement, until.kinetic_energy}) {
      require_argument(!value || std::isfinite(*value), "run_until's thresholds must be finite");
    }
    goal.max_cycles = static_cast<std::uint64_t>(until.max_cycles);
    // The engine's stop rule (dem/programme.h): all that are set, at once.
    if (until.stress || until.settlement) {
      const WallId wall = simulation_.find_wall(until.wall, until.wall_id);
      if (until.stress) goal.until.wall_stress_above = WallThreshold{wall, *until.stress};
      if (until.settlement) goal.until.wall_settlement_above = WallThreshold{wall, *until.settlement};
    }
    goal.until.kinetic_energy_below = until.kinetic_energy;
    goal.until.check_interval = until.check_interval > 0 ? static_cast<std::uint64_t>(until.check_interval) : 1;
  }
  // The first good state is a whole copy of the world: taken first, so a
  // copy that memory cannot hold fails the command with nothing started.
  HealthWatch health(simulation_.world());
  spdlog::info("request {} from {}: {} accepted, up to {} cycles from cycle {}", command.request_id, command.client_id,
               protocol::to_string(kind), goal.max_cycles, simulation_.world().cycle_count());
  active_.emplace(std::move(received), goal, simulation_.world());
  active_health_.emplace(std::move(health));
  owner_left_logged_ = false;
  lifecycle_.take(Transition::kStartRun);
  message_ = std::string(protocol::to_string(kind)) + " running";
  announce();
}

std::uint64_t SimulationRunner::chunk_cycles(std::uint64_t limit) const {
  const WorldSession& world = simulation_.world();
  const auto target = std::chrono::duration<double>(options_.chunk_duration).count();
  const auto by_rate = cycles_per_second_ > 0.0 ? static_cast<std::uint64_t>(cycles_per_second_ * target) : 1;
  return std::clamp<std::uint64_t>(
      std::min({by_rate, limit, schedule_.cycles_until_due(world.cycle_count(), world.time(), world.time_step())}), 1,
      kMaxChunk);
}

void SimulationRunner::timed(std::uint64_t cycles, const std::function<void()>& run) {
  const auto start = std::chrono::steady_clock::now();
  run();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (seconds > 0.0) {
    const double rate = static_cast<double>(cycles) / seconds;
    cycles_per_second_ = cycles_per_second_ > 0.0 ? 0.5 * (cycles_per_second_ + rate) : rate;
  }
}

void SimulationRunner::run_chunk() {
  WorldSession& world = simulation_.world();
  const std::uint64_t cycles = chunk_cycles(active_->cycles_to_next_stop());
  bool finished = false;
  try {
    timed(cycles,
          [&] { finished = active_->step(cycles, world); });  // the engine's stage runner: the cycles, then its check
  } catch (const std::exception& error) {
    // The step may have stopped half-way (memory ran out in it): the world
    // goes back to its last good state too.
    const std::string at = std::to_string(world.cycle_count());
    const std::string back = go_back_to(active_health_->last_good());
    fail_run("the engine failed at cycle " + at + ": " + failure_reason(error) + "; " + back);
    drop_lost_world();
    return;
  }
  // A blow-up's motion (not finite, a particle flung out) is looked for
  // after every chunk: it is what a blow-up reaches between two paced
  // assessments. Keeping a good state copies the world: memory that
  // cannot hold the copy fails the run (fail_anything_running).
  const bool suspect = world.motion_suspect();
  if (const auto problem = active_health_->check(world, finished || suspect)) {
    fail_unhealthy(*problem);
    return;
  }
  if (schedule_.due(world.cycle_count(), world.time())) publish_telemetry();
  if (!finished && checkpoints_.due(world.cycle_count())) {
    // Only a state found healthy is kept.
    if (const auto problem = active_health_->check(world, true)) {
      fail_unhealthy(*problem);
      return;
    }
    write_checkpoint(0, 0);
  }
  if (finished) {
    complete_run();
  } else {
    refresh_cache();
  }
}

// The last good state is written beside the case's tables and the world
// goes back to it; the server stays in error until a case or snapshot is loaded.
void SimulationRunner::fail_unhealthy(const StepHealth& problem) {
  const StateCheckpoint& good = active_health_->last_good();
  const std::filesystem::path path = recorder_.case_directory() / "last_good.snapshot";
  std::string written;
  try {
    io::write_snapshot_bytes(recorder_.own_file("last_good.snapshot"), good.bytes(simulation_.snapshot_info()));
    written = ", which is in " + path.string();
  } catch (const std::exception& error) {
    written = " (it could not be written: " + std::string(error.what()) + ")";
  }
  const std::string back = go_back_to(good);
  fail_run("the run is unhealthy " + problem.message + "; " + back + (world_lost_ ? "" : written));
  drop_lost_world();
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
  if (active_) {
    const std::string at = std::to_string(simulation_.world().cycle_count());
    const std::string back = go_back_to(active_health_->last_good());
    fail_run("the run failed at cycle " + at + ": " + failure_reason(error) + "; " + back);
    drop_lost_world();
  } else if (programme_ && programme_->outcome() == ProgrammeOutcome::kRunning) {
    programme_->fail("the engine thread ran into: " + failure_reason(error));
    end_programme();
  }
}

void SimulationRunner::complete_run() {
  const WorldSession& world = simulation_.world();
  std::string message =
      "ran " + std::to_string(active_->done()) + " cycles to cycle " + std::to_string(world.cycle_count());
  if (active_->condition_met())
    message = active_->condition() + " after " + std::to_string(active_->done()) + " cycles";
  if (world.cycle_count() != last_telemetry_cycle_) publish_telemetry();
  end_run(ReplyStatus::kOk, message);
}

void SimulationRunner::end_run(ReplyStatus status, const std::string& message, Transition transition) {
  protocol::Reply reply;
  reply.status = status;
  reply.message = message;
  reply.cycles_run = active_->done();
  reply.condition_met = active_->condition_met();
  const ReceivedCommand received = active_->command();
  active_.reset();
  active_health_.reset();
  lifecycle_.take(transition);
  message_ = message;
  announce();  // before the reply: who reads it sees the run ended
  send(received, std::move(reply));
}

void SimulationRunner::fail_run(const std::string& message) {
  spdlog::error("{}", message);
  end_run(ReplyStatus::kFailed, message, Transition::kFailRun);
}

void SimulationRunner::write_checkpoint(std::size_t stage, std::uint64_t stage_cycles) {
  try {
    checkpoints_.write(simulation_.world(), simulation_.snapshot_info(), recorder_, stage, stage_cycles);
  } catch (const std::exception& error) {
    // A checkpoint is insurance: its failure is said, the run goes on.
    spdlog::error("the checkpoint at cycle {} could not be written: {}", simulation_.world().cycle_count(),
                  error.what());
  }
}

}  // namespace dem::service
