#include "dem/service/simulation_runner.h"

#include <spdlog/spdlog.h>

#include "dem/io/file_access.h"
#include "dem/service/command_error.h"
#include "dem/service/command_limits.h"
#include "dem/service/world_snapshots.h"

namespace dem::service {

using protocol::CommandKind;
using protocol::ReplyStatus;
using protocol::ServerState;

namespace {

// How long an idle engine thread waits for a command before it looks at
// the shutdown flag again (a shutdown request also wakes it at once).
constexpr std::chrono::milliseconds kIdleWait{200};

// What clients may have the server read: the --read-dir directories, and
// nothing without them (not the directory it was started in, which may be
// "/": RELIABILITY.md, Files).
std::shared_ptr<const io::FileAccess> read_access(const ServerOptions& options) {
  return std::make_shared<const io::FileAccess>(options.read_directories);
}

// The initial case's own load also reads its directory (its particle
// files), which the operator named by starting the server with it.
std::shared_ptr<const io::FileAccess> initial_case_access(const ServerOptions& options,
                                                          const std::filesystem::path& path) {
  std::vector<std::filesystem::path> roots = options.read_directories;
  roots.push_back(std::filesystem::absolute(path).parent_path());
  return std::make_shared<const io::FileAccess>(roots);
}

// The commands that change what get_state reads (a load, a run); the
// others show only from the next cycle on.
bool changes_readout(std::uint8_t kind) {
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
      checkpoints_(options.checkpoints, options.programme_checkpoints) {}

void SimulationRunner::load_initial_case(const std::filesystem::path& path, bool resume) {
  protocol::LoadCaseArgs args;
  args.path = path.string();
  Simulation::Prepared prepared =
      simulation_.preparer().reading(initial_case_access(options_, path)).prepare_case(args);
  if (options_.run_programme && prepared.programme.stage_count() == 0) {
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
      restore_bytes(*prepared.world, latest->snapshot_bytes, latest->path.string());
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
  serve(false);
}

void SimulationRunner::serve(bool until_run_ends) {
  const auto take_waiting = [this] {
    for (ReceivedCommand& received : queue_.take_all()) {
      if (queue_.shutdown_requested()) {
        unanswered_.push_back(std::move(received));
      } else {
        execute(std::move(received));
      }
    }
  };
  while (run_going() || (!until_run_ends && !queue_.shutdown_requested())) {
    try {
      serve_once(take_waiting);
    } catch (const std::exception& error) {
      fail_anything_running(error);
    }
  }
}

// One turn of the loop: a chunk of the run going on and the commands that
// came meanwhile, or a command when none runs.
void SimulationRunner::serve_once(const std::function<void()>& take_waiting) {
  if (run_going()) {
    // Between two chunks: everything that arrived meanwhile, in order.
    take_waiting();
    if (!run_going() && !awaiting_refresh_.empty()) refresh_cache(true);  // the run ended among them
    if (run_going()) step_run();                                          // a stop or a shutdown request ends it
    if (run_going() && std::chrono::steady_clock::now() - last_status_ >= options_.progress_interval) {
      note_owner_left();
      publish_status();
    }
  } else if (std::optional<ReceivedCommand> received = queue_.pop(kIdleWait)) {
    execute(std::move(*received));
    take_waiting();
    refresh_cache();
  } else if (!awaiting_refresh_.empty()) {
    refresh_cache(true);  // a quiet moment: catch up
  }
}

void SimulationRunner::finish() {
  // An abandoned load is left to end on its own (it holds only copies):
  // shutting down does not wait for it.
  if (abandoned_) abandoned_->detach();
  abandoned_.reset();
  for (ReceivedCommand& received : queue_.take_all()) unanswered_.push_back(std::move(received));
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
    recorder_.finish(simulation_.world());
  }
  lifecycle_.take(Transition::kShutDown);
  // A one-shot server's last word keeps how its programme ended.
  message_ =
      (run_ ? message_ + "; " : std::string()) +
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
  // Only commands that change what get_state reads wait for it.
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
  const ServerState state_before = lifecycle_.state();
  const std::string message_before = message_;
  try {
    const std::optional<CommandKind> kind = protocol::command_kind(received.command.kind);
    if (!kind) {
      throw CommandError(ReplyStatus::kBadRequest, "unknown command kind " + std::to_string(received.command.kind));
    }
    if (const auto reason = lifecycle_.refusal(*kind)) {
      throw CommandError(ReplyStatus::kRefused, std::string(protocol::to_string(*kind)) + " refused: " + *reason);
    }
    check_command(received.command, options_.limits);
    if (*kind == CommandKind::kStop || *kind == CommandKind::kShutdown) {
      if (const auto reason = ownership_refusal(received)) {
        throw CommandError(ReplyStatus::kRefused, std::string(protocol::to_string(*kind)) + " refused: " + *reason);
      }
    }
    std::optional<protocol::Reply> answer = dispatch(received, *kind);
    if (!answer) return;  // a run started: its one reply comes when it ends
    reply = std::move(*answer);
  } catch (const CommandError& error) {
    reply.status = error.status();
    reply.message = error.what();
  } catch (const std::exception& error) {
    // Anything else a command runs into (a full disk, memory) fails that
    // command, not the server.
    reply.status = ReplyStatus::kFailed;
    reply.message = failure_reason(error);
  }
  // The status topic says what changed: a new state, a new case, a run -
  // before the reply, so who reads the reply finds the status to match.
  // Steering and queries change none of it; the next status carries
  // their count with it, so a flood of them does not flood the topic.
  if (lifecycle_.state() != state_before || message_ != message_before) announce();
  send(received, std::move(reply));
}

// What each command does, once the lifecycle, the limits and the run's
// owner have let it through.
std::optional<protocol::Reply> SimulationRunner::dispatch(const ReceivedCommand& received, CommandKind kind) {
  const protocol::Command& command = received.command;
  protocol::Reply reply;
  switch (kind) {
    case CommandKind::kCycle:
    case CommandKind::kRunUntil:
      start_command_run(received, kind);
      return std::nullopt;
    case CommandKind::kRunProgramme:
      run_programme(received);
      return std::nullopt;
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
  return reply;
}

}  // namespace dem::service
