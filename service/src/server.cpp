#include "dem/service/server.h"

#include <spdlog/spdlog.h>

#include <stdexcept>

#include "dem/protocol/topics.h"

namespace dem::service {

namespace {
ServerOptions checked(ServerOptions options) {
  if (!protocol::valid_server_name(options.name)) {
    throw std::invalid_argument("server name \"" + options.name +
                                "\" is not a ROS 2 name token (a letter, then letters, digits or underscores)");
  }
  if (options.resume && !options.initial_case) {
    throw std::invalid_argument("--resume needs the case whose checkpoints to resume (--case FILE)");
  }
  if (options.run_programme && !options.initial_case) {
    throw std::invalid_argument("a one-shot run (--run-and-exit) needs a case to run (--case FILE)");
  }
  return options;
}

// A peer that cannot meet the server is a warning; one that can (an older
// form, or no hash to judge) is worth a line.
void log_interface(const protocol::PeerVerdict& verdict) {
  using Kind = protocol::PeerVerdict::Kind;
  if (verdict.kind == Kind::kIncompatible || verdict.kind == Kind::kUnknownForm) {
    spdlog::warn("{}", verdict.text);
  } else {
    spdlog::info("{}", verdict.text);
  }
}
}  // namespace

Server::Server(ServerOptions options)
    : options_(checked(std::move(options))),
      queue_(options_.queue_capacity),
      participant_(options_.domain, options_.dds_config),
      interface_watch_(participant_, protocol::topics_of(options_.name), "this server", log_interface),
      name_claim_(participant_, options_.name, options_.name_discovery, options_.name_wait),
      telemetry_(participant_, options_.name),
      replies_(participant_, options_.name, options_.contact_chunk, options_.snapshot_chunk),
      runner_(options_, queue_, replies_, telemetry_, cache_),
      receiver_(participant_, options_.name, queue_, replies_, cache_) {
  runner_.set_writer_check([this](std::uint64_t writer) { return receiver_.writer_alive(writer); });
  if (options_.initial_case) runner_.load_initial_case(*options_.initial_case, options_.resume);
}

Server::~Server() {
  request_shutdown();
  wait();
}

void Server::start() {
  spdlog::info("server {} on DDS domain {} ({}), topics rt/dem/{}/...", options_.name, options_.domain,
               participant_.config(), options_.name);
  receiver_.start();
  engine_thread_ = std::thread([this] { engine_main(); });
}

void Server::engine_main() {
  if (options_.run_programme) {
    runner_.run_programme();
  } else {
    runner_.run();
  }
  // No more commands from here on; whatever is queued gets its reply in finish().
  receiver_.stop();
  runner_.finish();
}

void Server::request_shutdown() { queue_.request_shutdown(); }

void Server::wait() {
  if (engine_thread_.joinable()) engine_thread_.join();
}

}  // namespace dem::service
