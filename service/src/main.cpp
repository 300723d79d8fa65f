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
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <cstdlib>

#include "dem/service/background_load.h"
#include "dem/service/command_error.h"
#include "dem/service/name_claim.h"
#include "dem/service/server.h"
#include "server_command_line.h"
#include "signal_watcher.h"

namespace {

using namespace dem::service;

int exit_code(ProgrammeOutcome outcome) {
  switch (outcome) {
    case ProgrammeOutcome::kCompleted:
      return kServerDone;
    case ProgrammeOutcome::kStopped:
      return kServerStopped;
    case ProgrammeOutcome::kRunning:
    case ProgrammeOutcome::kPaused:  // a one-shot run never samples
    case ProgrammeOutcome::kFailed:
      break;
  }
  return kServerFailure;
}

void set_up_logging(const ServerCommandLine& line) {
  auto logger = spdlog::stderr_color_mt("dem_server");
  logger->set_pattern("[%Y-%m-%d %H:%M:%S.%e] [" + line.options.name + "] [%^%l%$] %v");
  spdlog::set_default_logger(logger);
  spdlog::set_level(spdlog::level::from_str(line.log_level));
}

// Serves until a shutdown command or a signal (or, one-shot, the end of
// the programme); the exit code.
int serve(const ServerOptions& options, SignalWatcher& signals) {
  try {
    Server server(options);
    signals.start([&server] { server.request_shutdown(); });
    server.start();
    server.wait();
    signals.stop();
    if (const auto outcome = server.programme_outcome()) return exit_code(*outcome);
    return kServerDone;
  } catch (const CommandError& error) {
    spdlog::error("the initial case cannot be loaded:\n{}", error.what());
    return kServerBadCase;
  } catch (const NameInUse& error) {
    spdlog::error("{}", error.what());
    return kServerNameInUse;
  } catch (const std::exception& error) {
    spdlog::error("{}", error.what());
    return kServerFailure;
  }
}

}  // namespace

int main(int argc, char** argv) {
  auto parsed = parse_server_command_line(argc, argv);
  if (const int* code = std::get_if<int>(&parsed)) return *code;
  const ServerCommandLine& line = std::get<ServerCommandLine>(parsed);
  set_up_logging(line);
  SignalWatcher signals;  // before the server starts its threads: they inherit the blocked signals
  const int code = serve(line.options, signals);
  // An abandoned load still running (background_load.h) holds copies
  // only, but static destructors at exit would race it.
  if (BackgroundLoad::running() > 0) {
    std::fflush(nullptr);
    std::_Exit(code);
  }
  return code;
}
