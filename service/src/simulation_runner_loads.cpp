// The engine thread's loads and snapshots: a new world installed (from a
// case or a snapshot, prepared in the background while stop and shutdown
// are still heard), and snapshots saved to or loaded from the output
// directory. The command loop is in simulation_runner.cpp.
#include <spdlog/spdlog.h>

#include "dem/io/file_access.h"
#include "dem/io/snapshot_file.h"
#include "dem/service/command_error.h"
#include "dem/service/simulation_runner.h"
#include "format_value.h"

namespace dem::service {

using protocol::CommandKind;
using protocol::ReplyStatus;

std::string SimulationRunner::install(Simulation::Prepared prepared, const io::ResumePoint* resume) {
  if (!resume) {
    // Before anything changes: a refused load leaves the server as it was.
    try {
      recorder_.claim(prepared.case_name, options_.overwrite);
    } catch (const OutputRecorder::OutputInUse& error) {
      throw CommandError(ReplyStatus::kRefused, error.what());
    }
  }
  if (simulation_.loaded()) recorder_.finish(simulation_.world());
  std::string message = simulation_.install(std::move(prepared));
  ++world_generation_;
  lifecycle_.take(Transition::kInstall);
  message_ = message;
  const WorldSession& world = simulation_.world();
  schedule_.published(world.cycle_count(), world.time());
  recorder_.start(simulation_.case_name(), world, simulation_.output(), resume);
  if (const auto& problem = recorder_.directory_problem()) spdlog::error("no tables or checkpoints: {}", *problem);
  checkpoints_.begin(recorder_.directory_problem() ? std::filesystem::path() : recorder_.case_directory(),
                     simulation_.case_digest(), world.cycle_count());
  publish_telemetry();
  return message;
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
  require_argument(args.transfer || !args.path.empty(), "save_snapshot needs a path, or transfer to return the bytes");
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
    require_argument(!args.data.empty(), "load_snapshot with transfer needs the snapshot's bytes");
    return install(prepare_in_background("load_snapshot",
                                         [preparer = simulation_.preparer(), data = args.data](std::function<bool()>) {
                                           return preparer.prepare_snapshot(data, "<transferred snapshot>");
                                         }));
  }
  require_argument(!args.path.empty(), "load_snapshot needs a path, or transfer with the bytes");
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

}  // namespace dem::service
