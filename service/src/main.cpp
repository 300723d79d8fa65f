// dem_server: one DEM simulation as a DDS service (docs/SERVICE.md).
//   dem_server --name NAME --domain ID [--case FILE] [--out DIR] ...
// Exit codes: 0 after a shutdown command, SIGINT or SIGTERM; 1 when DDS or
// the output fails; 2 bad arguments; 3 the initial case is invalid.
#include <signal.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <iostream>
#include <thread>

#include "dem/protocol/topics.h"
#include "dem/service/command_error.h"
#include "dem/service/server.h"

namespace {

constexpr int kFailure = 1;
constexpr int kBadArguments = 2;
constexpr int kBadCase = 3;

// SIGINT and SIGTERM are blocked in every thread and collected here with
// sigwait, so a signal is an ordinary event on an ordinary thread: it asks
// the server to shut down gracefully. SIGUSR1 (sent by stop()) ends the wait.
class SignalWatcher {
 public:
  SignalWatcher() {
    sigemptyset(&signals_);
    sigaddset(&signals_, SIGINT);
    sigaddset(&signals_, SIGTERM);
    sigaddset(&signals_, SIGUSR1);
    pthread_sigmask(SIG_BLOCK, &signals_, nullptr);  // before any thread starts: they inherit it
  }
  ~SignalWatcher() { stop(); }

  template <typename OnSignal>
  void start(OnSignal on_signal) {
    thread_ = std::thread([this, on_signal] {
      for (;;) {
        int signal = 0;
        if (sigwait(&signals_, &signal) != 0 || signal == SIGUSR1) return;
        spdlog::info("received {}: shutting down", signal == SIGINT ? "SIGINT" : "SIGTERM");
        on_signal();
      }
    });
  }
  void stop() {
    if (!thread_.joinable()) return;
    pthread_kill(thread_.native_handle(), SIGUSR1);
    thread_.join();
  }

 private:
  sigset_t signals_;
  std::thread thread_;
};

}  // namespace

int main(int argc, char** argv) {
  dem::service::ServerOptions options;
  CLI::App app{"Runs one DEM simulation as a service on Cyclone DDS (loopback by default), driven by commands and "
               "publishing plate forces, contact statistics and its status."};
  std::string log_level = "info";
  std::string initial_case;
  int threads = -1;
  bool no_csv = false;
  app.add_option("-n,--name", options.name, "server name; topics are rt/dem/<name>/...")->capture_default_str();
  app.add_option("-d,--domain", options.domain, "DDS domain id")->capture_default_str()->check(CLI::Range(0, 232));
  app.add_option("--dds-config", options.dds_config,
                 "Cyclone DDS configuration (file or URI); default $CYCLONEDDS_URI, else the repository's "
                 "loopback-only config/cyclonedds-loopback.xml");
  app.add_option("--telemetry-cycles", options.telemetry_cycles, "publish telemetry every N cycles (0: off)")
      ->capture_default_str();
  app.add_option("--telemetry-seconds", options.telemetry_seconds,
                 "publish telemetry every T seconds of simulated time (0: off)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error or off")
      ->capture_default_str()
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "critical", "off"}));
  app.add_option("--case", initial_case, "a case file to load at start");
  app.add_option("-o,--out", options.output_directory, "output directory: CSV tables per case, and snapshots")
      ->capture_default_str();
  app.add_option("-t,--threads", threads, "engine threads, 0 = all cores (default: the case's numerics.threads)")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--no-csv", no_csv, "write no CSV tables");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : kBadArguments;
  }
  if (!dem::protocol::valid_server_name(options.name)) {
    std::cerr << "error: --name \"" << options.name
              << "\" must be a ROS 2 name token: a letter, then letters, digits or underscores\n";
    return kBadArguments;
  }
  if (!initial_case.empty()) options.initial_case = initial_case;
  if (threads >= 0) options.threads = threads;
  options.record_csv = !no_csv;

  auto logger = spdlog::stderr_color_mt("dem_server");
  logger->set_pattern("[%Y-%m-%d %H:%M:%S.%e] [" + options.name + "] [%^%l%$] %v");
  spdlog::set_default_logger(logger);
  spdlog::set_level(spdlog::level::from_str(log_level));

  SignalWatcher signals;
  try {
    dem::service::Server server(options);
    signals.start([&server] { server.request_shutdown(); });
    server.start();
    server.wait();
    signals.stop();
  } catch (const dem::service::CommandError& error) {
    spdlog::error("the initial case cannot be loaded:\n{}", error.what());
    return kBadCase;
  } catch (const std::exception& error) {
    spdlog::error("{}", error.what());
    return kFailure;
  }
  return 0;
}
