#include "dem/service/simulation_runner.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

#include "dem/io/file_access.h"
#include "dem/io/snapshot_file.h"
#include "dem/service/command_error.h"
#include "dem/service/command_limits.h"
#include "dem/service/lifecycle.h"
#include "format_value.h"

namespace dem::service {

using protocol::CommandKind;
using protocol::ReplyStatus;
using protocol::ServerState;

namespace {

// How long an idle engine thread waits for a command before it looks at
// the shutdown flag again (a shutdown request also wakes it at once).
constexpr std::chrono::milliseconds kIdleWait{200};
constexpr std::uint64_t kMaxChunk = 1'000'000;

std::shared_ptr<const io::FileAccess> read_access(const ServerOptions& options) {
  std::vector<std::filesystem::path> roots = options.read_directories;
  if (roots.empty()) roots.push_back(std::filesystem::current_path());
  if (options.initial_case) roots.push_back(std::filesystem::absolute(*options.initial_case).parent_path());
  return std::make_shared<const io::FileAccess>(roots);
}

void require(bool condition, const std::string& message) {
  if (!condition) throw CommandError(ReplyStatus::kBadRequest, message);
}

}  // namespace

SimulationRunner::SimulationRunner(const ServerOptions& options, CommandQueue& queue, ReplySender& replies,
                                   TelemetryPublisher& telemetry, StateCache& cache)
    : options_(options),
      queue_(queue),
      replies_(replies),
      telemetry_(telemetry),
      cache_(cache),
      simulation_(options.threads, io::limits_with_budget(options.max_particles, options.memory_budget_bytes),
                  options.limits.max_query_contacts, read_access(options)),
      recorder_(options.output_directory, options.record_csv, options.vtk_interval),
      schedule_(options.telemetry_cycles, options.telemetry_seconds),
      checkpoints_(options.checkpoints) {}

void SimulationRunner::load_initial_case(const std::filesystem::path& path, bool resume) {
  protocol::LoadCaseArgs args;
  args.path = path.string();
  Simulation::Prepared prepared = simulation_.prepare_case(args);
  if (options_.run_programme && prepared.world->stage_count() == 0) {
    throw CommandError(ReplyStatus::kInvalidCase,
                       path.string() + ": the case defines no stages, so --run-and-exit has nothing to run");
  }
  if (resume) {
    // Where the checkpoints of this case are: the case directory install() will use.
    const io::CheckpointStore store(
        OutputRecorder::case_directory_of(options_.output_directory, prepared.case_name) / "checkpoints",
        options_.checkpoints.keep);
    std::optional<io::CheckpointStore::Latest> latest = store.latest();
    if (!latest) {
      throw CommandError(ReplyStatus::kNotFound, "--resume: no whole checkpoint in " + store.directory().string() +
                                                     " (start without --resume to begin afresh)");
    }
    if (latest->point.case_digest != prepared.digest) {
      throw CommandError(ReplyStatus::kInvalidCase,
                         "--resume: " + latest->path.string() + " belongs to another case (or this one changed since)");
    }
    try {
      prepared.world->restore_bytes(latest->snapshot_bytes, latest->path.string());
    } catch (const std::exception& error) {
      throw CommandError(ReplyStatus::kInvalidSnapshot, error.what());
    }
    resumed_ = std::move(latest->point);
    spdlog::info("resuming from the checkpoint at cycle {} ({})", resumed_->cycle, latest->path.string());
  }
  const std::string message = install(std::move(prepared), resumed_ ? &*resumed_ : nullptr);
  spdlog::info("{}", message);
}

// --- the loop ------------------------------------------------------------

void SimulationRunner::run() {
  publish_status();
  refresh_cache(true);
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
      if (!active_ && !awaiting_refresh_.empty()) refresh_cache(true);  // the run ended among them
      if (active_ && !queue_.shutdown_requested()) run_chunk();
      if (active_ && std::chrono::steady_clock::now() - last_status_ >= options_.progress_interval) {
        note_owner_left();
        publish_status();
      }
    } else if (std::optional<ReceivedCommand> received = queue_.pop(kIdleWait)) {
      execute(std::move(*received));
      for (ReceivedCommand& next : queue_.take_all()) {
        if (queue_.shutdown_requested()) {
          unanswered_.push_back(std::move(next));
        } else {
          execute(std::move(next));
        }
      }
      refresh_cache();
    } else if (!awaiting_refresh_.empty()) {
      refresh_cache(true);  // a quiet moment: catch up
    }
  }
}

void SimulationRunner::finish() {
  // An abandoned load is left to end on its own (it holds only copies):
  // shutting down does not wait for it.
  if (abandoned_) abandoned_->detach();
  abandoned_.reset();
  for (ReceivedCommand& received : queue_.take_all()) unanswered_.push_back(std::move(received));
  if (active_) end_run(ReplyStatus::kCancelled, "the server is shutting down");
  for (const ReceivedCommand& received : unanswered_) {
    queue_.done(received.command.client_id);
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
  message_ =
      (programme_ ? message_ + "; " : std::string()) +
      (simulation_.loaded() ? "shut down at cycle " + std::to_string(simulation_.world().cycle_count()) : "shut down");
  publish_status();
  using namespace std::chrono_literals;
  replies_.flush(2s);
  telemetry_.flush_status(2s);
  spdlog::info("{}; {} commands served, {} telemetry samples dropped", message_, cache_.served(), telemetry_.dropped());
}

// --- commands ------------------------------------------------------------

void SimulationRunner::execute(ReceivedCommand received) {
  // However it ends - a reply now, or a run started - the client's command
  // stops counting as pending (CommandQueue::pending) once the StateCache
  // shows its effect: until then that client's get_state waits its turn.
  // Only commands that change what get_state reads (a load, a run) wait
  // for it; the others show only from the next cycle on.
  const auto changes_readout = [](std::uint8_t kind) {
    switch (protocol::command_kind(kind).value_or(CommandKind::kGetState)) {
      case CommandKind::kLoadCase:
      case CommandKind::kLoadSnapshot:
      case CommandKind::kCycle:
      case CommandKind::kRunUntil:
      case CommandKind::kRunProgramme:
        return true;
      default:
        return false;
    }
  };
  struct Done {
    SimulationRunner& runner;
    std::string client;
    bool await_refresh;
    ~Done() {
      if (await_refresh) {
        runner.awaiting_refresh_.push_back(client);
      } else {
        runner.queue_.done(client);
      }
    }
  } done{*this, received.command.client_id, changes_readout(received.command.kind)};
  protocol::Reply reply;
  const protocol::Command& command = received.command;
  const ServerState state_before = state_;
  const std::string message_before = message_;
  try {
    const std::optional<CommandKind> kind = protocol::command_kind(command.kind);
    if (!kind) throw CommandError(ReplyStatus::kBadRequest, "unknown command kind " + std::to_string(command.kind));
    if (const auto reason = refusal(state_, *kind)) {
      throw CommandError(ReplyStatus::kRefused, std::string(protocol::to_string(*kind)) + " refused: " + *reason);
    }
    check_command(command, options_.limits);
    if (*kind == CommandKind::kStop || *kind == CommandKind::kShutdown) {
      if (const auto reason = ownership_refusal(received)) {
        throw CommandError(ReplyStatus::kRefused, std::string(protocol::to_string(*kind)) + " refused: " + *reason);
      }
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
        reply.message = install(prepare_in_background(
            "load_case", [preparer = simulation_.preparer(), args = command.load_case](std::function<bool()> stopped) {
              return preparer.stopped_by(std::move(stopped)).prepare_case(args);
            }));
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
  // The status topic says what changed: a new state, a new case, a run -
  // before the reply, so who reads the reply finds the status to match.
  // Steering and queries change none of it; the next status carries
  // their count with it, so a flood of them does not flood the topic.
  if (state_ != state_before || message_ != message_before) announce();
  send(received, std::move(reply));
}

std::string SimulationRunner::install(Simulation::Prepared prepared, const io::ResumePoint* resume) {
  if (simulation_.loaded()) simulation_.world().finish_tables(recorder_);
  std::string message = simulation_.install(std::move(prepared));
  ++world_generation_;
  state_ = ServerState::kLoaded;
  message_ = message;
  const WorldSession& world = simulation_.world();
  schedule_.published(world.cycle_count(), world.time());
  world.start_tables(recorder_, simulation_.case_name(), resume);
  if (const auto& problem = recorder_.directory_problem()) spdlog::error("no tables or checkpoints: {}", *problem);
  checkpoints_.begin(recorder_.directory_problem() ? std::filesystem::path() : recorder_.case_directory(),
                     simulation_.case_digest(), world.cycle_count());
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
    // The readout changes only with the world (a cycle, a load): wall
    // motions, servos and parameters show from the next cycle on. So it is
    // worked out once per state, however many ask.
    if (!readout_ || readout_->generation != world_generation_ || readout_->cycle != world.cycle_count()) {
      Readout readout{world_generation_, world.cycle_count(), {}, {}, 0};
      readout.plates.server = options_.name;
      readout.plates.cycle = world.cycle_count();
      readout.plates.time = world.time();
      readout.plates.walls = world.read_walls();
      readout.stats = world.read_contact_stats();
      readout.stats.server = options_.name;
      readout.stats.cycle = world.cycle_count();
      readout.stats.time = world.time();
      readout.hash = world.state_hash();
      readout_ = std::move(readout);
    }
    reply.plates = readout_->plates;
    reply.stats = readout_->stats;
    reply.plates.stamp = protocol::now_stamp();
    reply.stats.stamp = reply.plates.stamp;
    reply.state_hash = readout_->hash;
  }
  reply.message = std::string(protocol::to_string(state_)) +
                  (simulation_.loaded() ? ", case " + simulation_.case_name() + " at cycle " +
                                              std::to_string(simulation_.world().cycle_count())
                                        : std::string());
  return reply;
}

// Snapshot files live in the output directory: a relative path without
// "..", whose directories do not lead out by a link (io::inside_directory),
// so a client can neither read nor overwrite anything else.
std::filesystem::path SimulationRunner::snapshot_path(const std::string& requested) const {
  try {
    return std::filesystem::absolute(io::inside_directory(options_.output_directory, requested));
  } catch (const io::FileAccessError& error) {
    throw CommandError(ReplyStatus::kBadRequest, "snapshot paths are files in the server's output directory (" +
                                                     options_.output_directory.string() + "): " + error.what());
  }
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
    return install(prepare_in_background("load_snapshot",
                                         [preparer = simulation_.preparer(), data = args.data](std::function<bool()>) {
                                           return preparer.prepare_snapshot(data, "<transferred snapshot>");
                                         }));
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
  return install(prepare_in_background(
      "load_snapshot", [preparer = simulation_.preparer(), bytes = std::move(bytes), source = path.string()](
                           std::function<bool()>) { return preparer.prepare_snapshot(bytes, source); }));
}

Simulation::Prepared SimulationRunner::prepare_in_background(const std::string& what, BackgroundLoad::Prepare prepare) {
  if (abandoned_ && abandoned_->finished()) abandoned_.reset();
  if (abandoned_) {
    throw CommandError(ReplyStatus::kBusy, "busy: an abandoned load is still ending; send " + what + " again later");
  }
  auto load = std::make_unique<BackgroundLoad>(std::move(prepare));
  const auto deadline = std::chrono::steady_clock::now() + options_.load_time_limit;
  std::vector<ReceivedCommand> later;
  std::optional<std::string> abandon;
  while (!load->wait_for(options_.chunk_duration)) {
    // stop and shutdown now; the rest in order once the load is done.
    for (ReceivedCommand& received : queue_.take_all()) {
      const auto kind = protocol::command_kind(received.command.kind);
      if (kind == CommandKind::kStop) {
        abandon = what + " stopped by request before it was ready";
        protocol::Reply reply;
        reply.message = "stopped the " + what + " in preparation";
        send(received, std::move(reply));
        queue_.done(received.command.client_id);
      } else if (kind == CommandKind::kShutdown) {
        abandon = what + " given up: the server is shutting down";
        later.push_back(std::move(received));  // answered by the loop, which shuts down
      } else {
        later.push_back(std::move(received));
      }
    }
    if (!abandon && std::chrono::steady_clock::now() >= deadline) {
      abandon = what + ": preparing it took more than " +
                format_value(std::chrono::duration<double>(options_.load_time_limit).count()) +
                " s (--load-seconds); is there a random packing that nearly cannot fit?";
    }
    if (abandon) break;
  }
  queue_.put_back(std::move(later));
  if (abandon) {
    spdlog::warn("{}", *abandon);
    load->stop();
    abandoned_ = std::move(load);
    throw CommandError(abandon->find("stopped") != std::string::npos ? ReplyStatus::kCancelled : ReplyStatus::kFailed,
                       *abandon);
  }
  return load->take();
}

// --- who may stop a run ----------------------------------------------------

const ReceivedCommand* SimulationRunner::run_owner() const {
  if (active_) return &active_->command();
  return programme_command_;  // a one-shot programme has none: the server's own
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
  active_health_.emplace(simulation_.world());
  owner_left_logged_ = false;
  state_ = ServerState::kRunning;
  message_ = std::string(protocol::to_string(kind)) + " running";
  announce();
}

void SimulationRunner::run_chunk() {
  WorldSession& world = simulation_.world();
  const auto target = std::chrono::duration<double>(options_.chunk_duration).count();
  const auto by_rate = cycles_per_second_ > 0.0 ? static_cast<std::uint64_t>(cycles_per_second_ * target) : 1;
  const std::uint64_t cycles = std::clamp<std::uint64_t>(
      std::min({by_rate, active_->cycles_to_next_stop(),
                schedule_.cycles_until_due(world.cycle_count(), world.time(), world.time_step())}),
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
  // A blow-up's motion (not finite, a particle flung out) is looked for
  // after every chunk: it is what a blow-up reaches between two paced
  // assessments.
  const bool finished = active_->advance(cycles, world);
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
  WorldSession& world = simulation_.world();
  const StateCheckpoint& good = active_health_->last_good();
  const std::filesystem::path path = recorder_.case_directory() / "last_good.snapshot";
  std::string kept = "; the world is back at the last good state, cycle " + std::to_string(good.cycle());
  try {
    io::write_snapshot_bytes(recorder_.own_file("last_good.snapshot"), good.bytes(simulation_.snapshot_info()));
    kept += ", which is in " + path.string();
  } catch (const std::exception& error) {
    kept += " (it could not be written: " + std::string(error.what()) + ")";
  }
  world.restore(good);
  ++world_generation_;
  fail_run("the run is unhealthy " + problem.message + kept);
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

void SimulationRunner::end_run(ReplyStatus status, const std::string& message) {
  protocol::Reply reply;
  reply.status = status;
  reply.message = message;
  reply.cycles_run = active_->done();
  reply.condition_met = active_->condition_met();
  const ReceivedCommand received = active_->command();
  active_.reset();
  active_health_.reset();
  if (state_ == ServerState::kRunning) state_ = ServerState::kLoaded;
  message_ = message;
  announce();  // before the reply: who reads it sees the run ended
  send(received, std::move(reply));
}

void SimulationRunner::fail_run(const std::string& message) {
  state_ = ServerState::kError;
  spdlog::error("{}", message);
  end_run(ReplyStatus::kFailed, message);
}

// --- publishing ----------------------------------------------------------

void SimulationRunner::send(const ReceivedCommand& received, protocol::Reply reply) {
  reply.state = status();
  reply.state.commands_served = cache_.count_reply();
  replies_.send(received, std::move(reply));
}

protocol::Status SimulationRunner::status() const {
  protocol::Status s;
  s.server = options_.name;
  s.state = state_;
  s.message = message_;
  s.commands_served = cache_.served();
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
    s.progress =
        active_->total() > 0 ? static_cast<double>(active_->done()) / static_cast<double>(active_->total()) : 0.0;
  } else if (programme_ && state_ == ServerState::kRunning) {
    // A one-shot run's programme shows as a running command of no client.
    s.command = "programme";
    if (programme_command_) {
      s.command = "run_programme";
      s.command_client = programme_command_->command.client_id;
      s.command_request_id = programme_command_->command.request_id;
    }
    s.command_cycles_done = programme_->done(simulation_.world());
    s.command_cycles_total = programme_->total();
    s.progress = s.command_cycles_total > 0
                     ? static_cast<double>(s.command_cycles_done) / static_cast<double>(s.command_cycles_total)
                     : 0.0;
  }
  return s;
}

// A new state goes to the cache before the status topic: a client that
// sees a run start (or a case loaded) on the topic and then asks get_state
// is answered with that state, not the one before it.
void SimulationRunner::announce() {
  refresh_cache(true);
  publish_status();
}

void SimulationRunner::publish_status() {
  telemetry_.publish(status());
  last_status_ = std::chrono::steady_clock::now();
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

// After a chunk of cycles or a batch of commands, at a pace that costs at
// most about 1/40 of the engine thread's time (get_state reads every
// contact and hashes the state: on a large world that is not free), or
// `always` when a run ends. Meanwhile the cache is a little older (the
// replies say which cycle), and a client whose command it does not show
// yet has its get_state answered by the engine thread.
void SimulationRunner::refresh_cache(bool always) {
  if (!always && !refresh_pacing_.due()) return;
  refresh_pacing_.run([this] {
    protocol::Reply reply = get_state();
    reply.state = status();
    cache_.publish(std::move(reply));
  });
  for (const std::string& client : awaiting_refresh_) queue_.done(client);
  awaiting_refresh_.clear();
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
