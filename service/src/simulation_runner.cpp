#include "dem/service/simulation_runner.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

#include "dem/io/snapshot_file.h"
#include "dem/service/command_error.h"
#include "dem/service/lifecycle.h"

namespace dem::service {

using protocol::CommandKind;
using protocol::ReplyStatus;
using protocol::ServerState;

namespace {

// How long an idle engine thread waits for a command before it looks at
// the shutdown flag again (a shutdown request also wakes it at once).
constexpr std::chrono::milliseconds kIdleWait{200};
constexpr std::uint64_t kMaxChunk = 1'000'000;

void require(bool condition, const std::string& message) {
  if (!condition) throw CommandError(ReplyStatus::kBadRequest, message);
}

}  // namespace

SimulationRunner::SimulationRunner(const ServerOptions& options, CommandQueue& queue, ReplySender& replies,
                                   TelemetryPublisher& telemetry)
    : options_(options),
      queue_(queue),
      replies_(replies),
      telemetry_(telemetry),
      simulation_(options.threads),
      recorder_(options.output_directory, options.record_csv, options.vtk_interval),
      schedule_(options.telemetry_cycles, options.telemetry_seconds) {}

void SimulationRunner::load_initial_case(const std::filesystem::path& path) {
  protocol::LoadCaseArgs args;
  args.path = path.string();
  Simulation::Prepared prepared = simulation_.prepare_case(args);
  if (options_.run_programme && prepared.world->stage_count() == 0) {
    throw CommandError(ReplyStatus::kInvalidCase,
                       path.string() + ": the case defines no stages, so --run-and-exit has nothing to run");
  }
  const std::string message = install(std::move(prepared));
  spdlog::info("{}", message);
}

// --- the loop ------------------------------------------------------------

void SimulationRunner::run() {
  publish_status();
  while (!queue_.shutdown_requested()) {
    if (active_) {
      // Between two chunks: everything that arrived meanwhile, in order.
      for (ReceivedCommand& received : queue_.take_all()) {
        if (queue_.shutdown_requested()) {
          unanswered_.push_back(std::move(received));
        } else {
          execute(std::move(received));
        }
      }
      if (active_ && !queue_.shutdown_requested()) run_chunk();
      if (active_ && std::chrono::steady_clock::now() - last_status_ >= options_.progress_interval) publish_status();
    } else if (std::optional<ReceivedCommand> received = queue_.pop(kIdleWait)) {
      execute(std::move(*received));
    }
  }
}

void SimulationRunner::finish() {
  for (ReceivedCommand& received : queue_.take_all()) unanswered_.push_back(std::move(received));
  if (active_) end_run(ReplyStatus::kCancelled, "the server is shutting down");
  for (const ReceivedCommand& received : unanswered_) {
    protocol::Reply reply;
    reply.status = ReplyStatus::kShuttingDown;
    reply.message = "not done: the server is shutting down";
    send(received, std::move(reply));
  }
  unanswered_.clear();
  if (simulation_.loaded()) {
    if (simulation_.world().cycle_count() != last_telemetry_cycle_ || !telemetry_published_) publish_telemetry();
    simulation_.world().finish_tables(recorder_);
  }
  state_ = ServerState::kShutdown;
  // A one-shot server's last word keeps how its programme ended.
  message_ = (programme_ ? message_ + "; " : std::string()) +
             (simulation_.loaded() ? "shut down at cycle " + std::to_string(simulation_.world().cycle_count())
                                   : "shut down");
  publish_status();
  using namespace std::chrono_literals;
  replies_.flush(2s);
  telemetry_.flush_status(2s);
  spdlog::info("{}; {} commands served, {} telemetry samples dropped", message_, commands_served_,
               telemetry_.dropped());
}

// --- commands ------------------------------------------------------------

void SimulationRunner::execute(ReceivedCommand received) {
  protocol::Reply reply;
  const protocol::Command& command = received.command;
  try {
    const std::optional<CommandKind> kind = protocol::command_kind(command.kind);
    if (!kind) throw CommandError(ReplyStatus::kBadRequest, "unknown command kind " + std::to_string(command.kind));
    if (const auto reason = refusal(state_, *kind)) {
      throw CommandError(ReplyStatus::kRefused, std::string(protocol::to_string(*kind)) + " refused: " + *reason);
    }
    switch (*kind) {
      case CommandKind::kCycle:
      case CommandKind::kRunUntil:
        start_run(received, *kind);
        return;  // its one reply comes when it ends
      case CommandKind::kRunProgramme:
        run_programme(received);
        return;  // replied to when the stages end
      case CommandKind::kLoadCase:
        reply.message = install(simulation_.prepare_case(command.load_case));
        reply.path = command.load_case.path;
        break;
      case CommandKind::kSetWallVelocity:
        reply.message = simulation_.set_wall_velocity(command.wall_velocity);
        break;
      case CommandKind::kSetWallServo:
        reply.message = simulation_.set_wall_servo(command.wall_servo);
        break;
      case CommandKind::kStop:
        reply.message = stop();
        break;
      case CommandKind::kGetState:
        reply = get_state();
        break;
      case CommandKind::kShutdown:
        queue_.request_shutdown();
        reply.message = "shutting down";
        break;
      case CommandKind::kQueryContacts:
        reply.contacts = simulation_.query_contacts(command.query);
        reply.total_contacts = reply.contacts.size();
        reply.message = std::to_string(reply.total_contacts) + " contacts at cycle " +
                        std::to_string(simulation_.world().cycle_count());
        break;
      case CommandKind::kSaveSnapshot:
        reply = save_snapshot(command.snapshot);
        break;
      case CommandKind::kLoadSnapshot:
        reply.message = load_snapshot(command.snapshot);
        break;
      case CommandKind::kSetParameter:
        reply.message = simulation_.set_parameter(command.parameter);
        break;
    }
  } catch (const CommandError& error) {
    reply.status = error.status();
    reply.message = error.what();
  } catch (const std::exception& error) {
    // Anything else a command runs into (a full disk, memory) fails that
    // command, not the server.
    reply.status = ReplyStatus::kFailed;
    reply.message = error.what();
  }
  send(received, std::move(reply));
  publish_status();
}

std::string SimulationRunner::install(Simulation::Prepared prepared) {
  if (simulation_.loaded()) simulation_.world().finish_tables(recorder_);
  std::string message = simulation_.install(std::move(prepared));
  state_ = ServerState::kLoaded;
  message_ = message;
  const WorldSession& world = simulation_.world();
  schedule_.published(world.cycle_count(), world.time());
  world.start_tables(recorder_, simulation_.case_name());
  publish_telemetry();
  return message;
}

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

protocol::Reply SimulationRunner::get_state() const {
  protocol::Reply reply;
  if (simulation_.loaded()) {
    const WorldSession& world = simulation_.world();
    reply.plates.server = options_.name;
    reply.plates.cycle = world.cycle_count();
    reply.plates.time = world.time();
    reply.plates.stamp = protocol::now_stamp();
    reply.plates.walls = world.read_walls();
    reply.stats = world.read_contact_stats();
    reply.stats.server = options_.name;
    reply.stats.cycle = world.cycle_count();
    reply.stats.time = world.time();
    reply.stats.stamp = reply.plates.stamp;
    reply.state_hash = world.state_hash();
  }
  reply.message = std::string(protocol::to_string(state_)) +
                  (simulation_.loaded() ? ", case " + simulation_.case_name() + " at cycle " +
                                              std::to_string(simulation_.world().cycle_count())
                                        : std::string());
  return reply;
}

// Snapshot files live in the output directory: a relative path without
// "..", so a client can neither read nor overwrite anything else.
std::filesystem::path SimulationRunner::snapshot_path(const std::string& requested) const {
  const std::filesystem::path path(requested);
  require(!path.empty() && path.is_relative(),
          "snapshot paths are relative to the server's output directory (" + options_.output_directory.string() +
              "), got \"" + requested + "\"");
  for (const auto& part : path) require(part != "..", "snapshot paths may not leave the output directory");
  return std::filesystem::absolute(options_.output_directory / path);
}

protocol::Reply SimulationRunner::save_snapshot(const protocol::SnapshotArgs& args) {
  require(args.transfer || !args.path.empty(), "save_snapshot needs a path, or transfer to return the bytes");
  std::filesystem::path path;
  if (!args.path.empty()) path = snapshot_path(args.path);
  protocol::Reply reply;
  std::string bytes = simulation_.snapshot_bytes();
  const std::string at = "snapshot of " + simulation_.case_name() + " at cycle " +
                         std::to_string(simulation_.world().cycle_count()) + " (" + std::to_string(bytes.size()) +
                         " bytes)";
  reply.total_bytes = bytes.size();
  if (!path.empty()) {
    try {
      io::write_snapshot_bytes(path, bytes);
    } catch (const io::SnapshotError& error) {
      throw CommandError(ReplyStatus::kFailed, error.what());
    }
    reply.path = path.string();
    reply.message = "saved " + at + " to " + reply.path;
  } else {
    reply.message = "sending " + at;
  }
  if (args.transfer) reply.data = std::move(bytes);
  return reply;
}

std::string SimulationRunner::load_snapshot(const protocol::SnapshotArgs& args) {
  if (args.transfer) {
    require(!args.data.empty(), "load_snapshot with transfer needs the snapshot's bytes");
    return install(simulation_.prepare_snapshot(args.data, "<transferred snapshot>"));
  }
  require(!args.path.empty(), "load_snapshot needs a path, or transfer with the bytes");
  const std::filesystem::path path = snapshot_path(args.path);
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw CommandError(ReplyStatus::kNotFound, "no snapshot " + path.string() + " on the server");
  }
  std::string bytes;
  try {
    bytes = io::read_snapshot_bytes(path);
  } catch (const io::SnapshotError& read_error) {
    throw CommandError(ReplyStatus::kFailed, read_error.what());
  }
  return install(simulation_.prepare_snapshot(bytes, path.string()));
}

// --- running commands ------------------------------------------------------

void SimulationRunner::start_run(ReceivedCommand& received, CommandKind kind) {
  const protocol::Command& command = received.command;
  RunGoal goal;
  if (kind == CommandKind::kCycle) {
    require(command.cycle.cycles > 0, "the cycle count must be > 0, got " + std::to_string(command.cycle.cycles));
    goal.max_cycles = static_cast<std::uint64_t>(command.cycle.cycles);
  } else {
    const protocol::RunUntilArgs& until = command.run_until;
    require(until.max_cycles > 0, "run_until needs a maximum cycle count > 0, got " + std::to_string(until.max_cycles));
    require(until.check_interval >= 0, "the check interval must be >= 0");
    require(until.stress || until.settlement || until.kinetic_energy,
            "run_until needs a condition: a plate's stress or settlement, or the kinetic energy");
    for (const auto& value : {until.stress, until.settlement, until.kinetic_energy}) {
      require(!value || std::isfinite(*value), "run_until's thresholds must be finite");
    }
    if (until.stress || until.settlement) goal.wall = simulation_.find_wall(until.wall, until.wall_id);
    goal.max_cycles = static_cast<std::uint64_t>(until.max_cycles);
    goal.stress = until.stress;
    goal.settlement = until.settlement;
    goal.kinetic_energy = until.kinetic_energy;
    goal.check_interval = until.check_interval > 0 ? static_cast<std::uint64_t>(until.check_interval) : 1;
  }
  spdlog::info("request {} from {}: {} accepted, up to {} cycles from cycle {}", command.request_id, command.client_id,
               protocol::to_string(kind), goal.max_cycles, simulation_.world().cycle_count());
  active_.emplace(std::move(received), goal, simulation_.world());
  state_ = ServerState::kRunning;
  message_ = std::string(protocol::to_string(kind)) + " running";
  publish_status();
}

void SimulationRunner::run_chunk() {
  WorldSession& world = simulation_.world();
  const auto target = std::chrono::duration<double>(options_.chunk_duration).count();
  const auto by_rate = cycles_per_second_ > 0.0 ? static_cast<std::uint64_t>(cycles_per_second_ * target) : 1;
  const std::uint64_t cycles =
      std::clamp<std::uint64_t>(std::min({by_rate, active_->cycles_to_next_stop(),
                                          schedule_.cycles_until_due(world.cycle_count(), world.time(),
                                                                     world.time_step())}),
                                1, kMaxChunk);
  const auto start = std::chrono::steady_clock::now();
  try {
    world.cycle(cycles);
  } catch (const std::exception& error) {
    fail_run("the engine failed at cycle " + std::to_string(world.cycle_count()) + ": " + error.what());
    return;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (seconds > 0.0) {
    const double rate = static_cast<double>(cycles) / seconds;
    cycles_per_second_ = cycles_per_second_ > 0.0 ? 0.5 * (cycles_per_second_ + rate) : rate;
  }
  if (!std::isfinite(world.kinetic_energy())) {
    fail_run("the simulation blew up at cycle " + std::to_string(world.cycle_count()) +
             ": the kinetic energy is not finite (is the time step too large?)");
    return;
  }
  if (schedule_.due(world.cycle_count(), world.time())) publish_telemetry();
  if (active_->advance(cycles, world)) complete_run();
}

void SimulationRunner::complete_run() {
  const WorldSession& world = simulation_.world();
  std::string message = "ran " + std::to_string(active_->done()) + " cycles to cycle " +
                        std::to_string(world.cycle_count());
  if (active_->condition_met()) message = active_->condition() + " after " + std::to_string(active_->done()) + " cycles";
  if (world.cycle_count() != last_telemetry_cycle_) publish_telemetry();
  end_run(ReplyStatus::kOk, message);
}

void SimulationRunner::end_run(ReplyStatus status, const std::string& message) {
  protocol::Reply reply;
  reply.status = status;
  reply.message = message;
  reply.cycles_run = active_->done();
  reply.condition_met = active_->condition_met();
  const ReceivedCommand received = active_->command();
  active_.reset();
  if (state_ == ServerState::kRunning) state_ = ServerState::kLoaded;
  message_ = message;
  send(received, std::move(reply));
  publish_status();
}

void SimulationRunner::fail_run(const std::string& message) {
  state_ = ServerState::kError;
  spdlog::error("{}", message);
  end_run(ReplyStatus::kFailed, message);
}

// --- publishing ----------------------------------------------------------

void SimulationRunner::send(const ReceivedCommand& received, protocol::Reply reply) {
  ++commands_served_;
  reply.state = status();
  replies_.send(received, std::move(reply));
}

protocol::Status SimulationRunner::status() const {
  protocol::Status s;
  s.server = options_.name;
  s.state = state_;
  s.message = message_;
  s.commands_served = commands_served_;
  s.telemetry_dropped = telemetry_.dropped();
  s.stamp = protocol::now_stamp();
  if (simulation_.loaded()) {
    const WorldSession& world = simulation_.world();
    s.case_name = simulation_.case_name();
    s.dimension = simulation_.dimension();
    s.particles = world.particle_count();
    s.walls = world.wall_count();
    s.cycle = world.cycle_count();
    s.time = world.time();
    s.time_step = world.time_step();
  }
  if (active_) {
    const protocol::Command& command = active_->command().command;
    s.command = std::string(protocol::to_string(*protocol::command_kind(command.kind)));
    s.command_client = command.client_id;
    s.command_request_id = command.request_id;
    s.command_cycles_done = active_->done();
    s.command_cycles_total = active_->total();
    s.progress = active_->total() > 0 ? static_cast<double>(active_->done()) / static_cast<double>(active_->total()) : 0.0;
  } else if (programme_ && state_ == ServerState::kRunning) {
    // A one-shot run's programme shows as a running command of no client.
    s.command = "programme";
    if (programme_command_) {
      s.command = "run_programme";
      s.command_client = programme_command_->client_id;
      s.command_request_id = programme_command_->request_id;
    }
    s.command_cycles_done = programme_->done(simulation_.world());
    s.command_cycles_total = programme_->total();
    s.progress = s.command_cycles_total > 0
                     ? static_cast<double>(s.command_cycles_done) / static_cast<double>(s.command_cycles_total)
                     : 0.0;
  }
  return s;
}

void SimulationRunner::publish_status() {
  telemetry_.publish(status());
  last_status_ = std::chrono::steady_clock::now();
}

void SimulationRunner::publish_telemetry() {
  const WorldSession& world = simulation_.world();
  protocol::PlateForces plates;
  plates.server = options_.name;
  plates.cycle = world.cycle_count();
  plates.time = world.time();
  plates.stamp = protocol::now_stamp();
  plates.walls = world.read_walls();
  protocol::ContactStats stats = world.read_contact_stats();
  stats.server = options_.name;
  stats.cycle = plates.cycle;
  stats.time = plates.time;
  stats.stamp = plates.stamp;
  telemetry_.publish(plates, stats);
  if (std::optional<protocol::RegionTelemetry> regions = world.read_regions()) {
    regions->server = options_.name;
    regions->cycle = plates.cycle;
    regions->time = plates.time;
    regions->stamp = plates.stamp;
    telemetry_.publish(*regions);
  }
  // A one-shot run writes its rows at the case's output interval instead.
  if (!programme_) world.record_tables(recorder_);
  schedule_.published(world.cycle_count(), world.time());
  last_telemetry_cycle_ = world.cycle_count();
  telemetry_published_ = true;
}

}  // namespace dem::service
