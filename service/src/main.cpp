// dem_server: one DEM simulation as a DDS service (docs/SERVICE.md).
//   dem_server --name NAME --domain ID [--case FILE] [--out DIR] ...
//   dem_server --case FILE --run-and-exit ...   (one-shot: the case's programme)
// Options may also come from the environment (DEM_SERVER, DEM_DOMAIN,
// DEM_CASE, ...: a container or a batch script configures it that way).
// Exit codes: 0 after a shutdown command, SIGINT or SIGTERM, or a one-shot
// programme that ran to its end; 1 when DDS or the output fails, or the
// one-shot run failed; 2 bad arguments; 3 the initial case is invalid;
// 4 a one-shot programme stopped before its end; 5 another server of the
// same name is on the domain, or took the name starting at the same time.
#include <signal.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <thread>

#include "dem/io/resource_limits.h"
#include "dem/protocol/topics.h"
#include "dem/service/background_load.h"
#include "dem/service/command_error.h"
#include "dem/service/name_claim.h"
#include "dem/service/server.h"
#include "dem/version.h"

namespace {

constexpr int kFailure = 1;
constexpr int kBadArguments = 2;
constexpr int kBadCase = 3;
constexpr int kStopped = 4;
constexpr int kNameInUse = 5;

int exit_code(dem::service::ProgrammeOutcome outcome) {
  switch (outcome) {
    case dem::service::ProgrammeOutcome::kCompleted:
      return 0;
    case dem::service::ProgrammeOutcome::kStopped:
      return kStopped;
    case dem::service::ProgrammeOutcome::kRunning:
    case dem::service::ProgrammeOutcome::kFailed:
      break;
  }
  return kFailure;
}

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
  CLI::App app{
      "Runs one DEM simulation as a service on Cyclone DDS (loopback by default), driven by commands and "
      "publishing plate forces, contact statistics and its status."};
  app.set_version_flag("--version", "dem_server " DEM_VERSION);
  std::string log_level = "info";
  std::string initial_case;
  int threads = -1;
  bool no_csv = false;
  app.add_option("-n,--name", options.name, "server name; topics are rt/dem/<name>/...")
      ->capture_default_str()
      ->envname("DEM_SERVER");
  app.add_option("-d,--domain", options.domain, "DDS domain id")
      ->capture_default_str()
      ->check(CLI::Range(0, 232))
      ->envname("DEM_DOMAIN");
  app.add_option("--dds-config", options.dds_config,
                 "Cyclone DDS configuration (file or URI); default $CYCLONEDDS_URI, else the repository's "
                 "loopback-only config/cyclonedds-loopback.xml");
  app.add_option("--telemetry-cycles", options.telemetry_cycles, "publish telemetry every N cycles (0: off)")
      ->capture_default_str()
      ->envname("DEM_TELEMETRY_CYCLES");
  app.add_option("--telemetry-seconds", options.telemetry_seconds,
                 "publish telemetry every T seconds of simulated time (0: off)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber)
      ->envname("DEM_TELEMETRY_SECONDS");
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error or off")
      ->capture_default_str()
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "critical", "off"}))
      ->envname("DEM_LOG_LEVEL");
  CLI::Option* case_option =
      app.add_option("--case", initial_case, "a case file to load at start")->envname("DEM_CASE");
  app.add_option("-o,--out", options.output_directory, "output directory: CSV tables per case, and snapshots")
      ->capture_default_str()
      ->envname("DEM_OUT");
  app.add_option("-t,--threads", threads, "engine threads, 0 = all cores (default: the case's numerics.threads)")
      ->check(CLI::NonNegativeNumber)
      ->envname("DEM_THREADS");
  app.add_flag("--no-csv", no_csv, "write no CSV tables");
  std::uint64_t vtk_interval = 0;
  CLI::Option* vtk_option =
      app.add_option("--vtk-interval", vtk_interval,
                     "cycles between the ParaView files (particles.pvd, contacts.pvd, walls.pvd, vtk/) of the "
                     "programmes it runs; 0 = none (default: each case's output.vtk_interval)")
          ->check(CLI::NonNegativeNumber)
          ->envname("DEM_VTK_INTERVAL");
  app.add_option("--read-dir", options.read_directories,
                 "a directory load_case may read cases (and cases their particle files) from; repeat for more "
                 "(default: none - clients send their cases; the --case file's own load reads its directory)")
      ->envname("DEM_READ_DIRS")
      ->delimiter(':');
  double name_wait = 12.0;
  app.add_option("--name-wait", name_wait,
                 "seconds to wait for another server of this name to leave before refusing to start (one that "
                 "died keeps its name until its DDS lease, 10 s, runs out)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber)
      ->envname("DEM_NAME_WAIT");
  int load_seconds = 120;
  app.add_option("--load-seconds", load_seconds,
                 "a case or snapshot still preparing after this many seconds is abandoned with an error")
      ->capture_default_str()
      ->check(CLI::PositiveNumber)
      ->envname("DEM_LOAD_SECONDS");
  CLI::Option* checkpoint_cycles =
      app.add_option("--checkpoint-cycles", options.checkpoints.cycles,
                     "write a checkpoint to <out>/<case>/checkpoints every N cycles (0: none); without this or "
                     "--checkpoint-seconds, programmes (--run-and-exit, run_programme) write a first one 5 s into "
                     "the run and then one every 300 s, cycle and run_until none")
          ->envname("DEM_CHECKPOINT_CYCLES");
  CLI::Option* checkpoint_seconds = app.add_option("--checkpoint-seconds", options.checkpoints.seconds,
                                                   "write a checkpoint every S seconds of wall time (0: none)")
                                        ->check(CLI::NonNegativeNumber)
                                        ->envname("DEM_CHECKPOINT_SECONDS");
  app.add_option("--checkpoint-keep", options.checkpoints.keep, "checkpoints kept (the newest)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber)
      ->envname("DEM_CHECKPOINT_KEEP");
  app.add_flag("--resume", options.resume,
               "continue the --case from its newest checkpoint in <out>/<case>/checkpoints, appending to its tables "
               "(with --run-and-exit: from where its programme stood)")
      ->needs(case_option)
      ->envname("DEM_RESUME");
  app.add_flag("--overwrite", options.overwrite,
               "replace the output of an earlier run in <out>/<case>/ (its tables, snapshots and checkpoints) when "
               "a case is loaded afresh; without it such a load is refused, so nothing is cut unasked")
      ->excludes("--resume")
      ->envname("DEM_OVERWRITE");
  app.add_option("--queue-capacity", options.queue_capacity,
                 "commands waiting for the engine; beyond them a command is answered busy")
      ->capture_default_str()
      ->check(CLI::PositiveNumber)
      ->envname("DEM_QUEUE_CAPACITY");
  app.add_option("--max-particles", options.max_particles,
                 "particles one case or snapshot may hold (0: as many as the memory budget holds)")
      ->capture_default_str()
      ->envname("DEM_MAX_PARTICLES");
  app.add_option("--memory-budget", options.memory_budget_bytes,
                 "bytes one world may need, at 2.5 kB a particle (0: half the machine's memory)")
      ->capture_default_str()
      ->envname("DEM_MEMORY_BUDGET");
  app.add_option("--max-cycles", options.limits.max_cycles, "cycles one command may run")
      ->capture_default_str()
      ->check(CLI::PositiveNumber)
      ->envname("DEM_MAX_CYCLES");
  app.add_option("--max-payload-bytes", options.limits.max_payload_bytes,
                 "bytes of case text, case or snapshot one command may carry")
      ->capture_default_str()
      ->check(CLI::PositiveNumber)
      ->envname("DEM_MAX_PAYLOAD_BYTES");
  app.add_option("--max-query-contacts", options.limits.max_query_contacts, "contacts one query may return")
      ->capture_default_str()
      ->check(CLI::PositiveNumber)
      ->envname("DEM_MAX_QUERY_CONTACTS");
  app.add_flag("--run-and-exit", options.run_programme,
               "one-shot: run the case's loading programme (its stages), publishing telemetry and answering "
               "commands meanwhile; write the tables and <out>/<case>/final.snapshot (after a failure "
               "last_good.snapshot) and exit: 0 done, 1 failed, 4 stopped before its end")
      ->needs(case_option)
      ->envname("DEM_RUN_AND_EXIT");
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
  if (threads >= 0) {
    if (const auto problem = dem::io::thread_count_problem(threads, dem::io::machine_limits())) {
      std::cerr << "error: --threads " << *problem << '\n';
      return kBadArguments;
    }
    options.threads = threads;
  }
  // Asked for, checkpoints are the same for every run (both 0: none at all);
  // otherwise programmes keep their default.
  if (checkpoint_cycles->count() > 0 || checkpoint_seconds->count() > 0) {
    options.programme_checkpoints = options.checkpoints;
  }
  options.programme_checkpoints.keep = options.checkpoints.keep;
  options.record_csv = !no_csv;
  if (vtk_option->count() > 0) options.vtk_interval = vtk_interval;
  options.load_time_limit = std::chrono::seconds(load_seconds);
  options.name_wait = std::chrono::milliseconds(static_cast<std::int64_t>(name_wait * 1000));

  auto logger = spdlog::stderr_color_mt("dem_server");
  logger->set_pattern("[%Y-%m-%d %H:%M:%S.%e] [" + options.name + "] [%^%l%$] %v");
  spdlog::set_default_logger(logger);
  spdlog::set_level(spdlog::level::from_str(log_level));

  SignalWatcher signals;
  int code = 0;
  try {
    dem::service::Server server(options);
    signals.start([&server] { server.request_shutdown(); });
    server.start();
    server.wait();
    signals.stop();
    if (const auto outcome = server.programme_outcome()) code = exit_code(*outcome);
  } catch (const dem::service::CommandError& error) {
    spdlog::error("the initial case cannot be loaded:\n{}", error.what());
    code = kBadCase;
  } catch (const dem::service::NameInUse& error) {
    spdlog::error("{}", error.what());
    code = kNameInUse;
  } catch (const std::exception& error) {
    spdlog::error("{}", error.what());
    code = kFailure;
  }
  // An abandoned load still running (background_load.h) holds copies
  // only, but static destructors at exit would race it.
  if (dem::service::BackgroundLoad::running() > 0) {
    std::fflush(nullptr);
    std::_Exit(code);
  }
  return code;
}
