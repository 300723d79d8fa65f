#include "server_command_line.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdint>
#include <iostream>

#include "dem/io/resource_limits.h"
#include "dem/protocol/topics.h"
#include "dem/version.h"

namespace dem::service {
namespace {

// What the options are parsed into before they become ServerOptions: the
// values whose absence means "the case's" or "the default".
struct Parsed {
  ServerCommandLine line;
  std::string initial_case;
  int threads = -1;
  bool no_csv = false;
  std::uint64_t vtk_interval = 0;
  double name_wait = 12.0;
  int load_seconds = 120;
  CLI::Option* case_option = nullptr;
  CLI::Option* vtk_option = nullptr;
  CLI::Option* checkpoint_cycles = nullptr;
  CLI::Option* checkpoint_seconds = nullptr;
};

// Who the server is on DDS, and how it logs.
void add_identity(CLI::App& app, Parsed& p) {
  ServerOptions& o = p.line.options;
  app.add_option("-n,--name", o.name, "server name; topics are rt/dem/<name>/...")
      ->capture_default_str()
      ->envname("DEM_SERVER");
  app.add_option("-d,--domain", o.domain, "DDS domain id")
      ->capture_default_str()
      ->check(CLI::Range(0, 232))
      ->envname("DEM_DOMAIN");
  app.add_option("--dds-config", o.dds_config,
                 "Cyclone DDS configuration (file or URI); default $CYCLONEDDS_URI, else the repository's "
                 "loopback-only config/cyclonedds-loopback.xml");
  app.add_option("--telemetry-cycles", o.telemetry_cycles, "publish telemetry every N cycles (0: off)")
      ->capture_default_str()
      ->envname("DEM_TELEMETRY_CYCLES");
  app.add_option("--telemetry-seconds", o.telemetry_seconds,
                 "publish telemetry every T seconds of simulated time (0: off)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber)
      ->envname("DEM_TELEMETRY_SECONDS");
  app.add_option("--log-level", p.line.log_level, "trace, debug, info, warn, error or off")
      ->capture_default_str()
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "critical", "off"}))
      ->envname("DEM_LOG_LEVEL");
  app.add_option("--name-wait", p.name_wait,
                 "seconds to wait for another server of this name to leave before refusing to start (one that "
                 "died keeps its name until its DDS lease, 10 s, runs out)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber)
      ->envname("DEM_NAME_WAIT");
}

// What it runs at start, and what it reads.
void add_case(CLI::App& app, Parsed& p) {
  ServerOptions& o = p.line.options;
  p.case_option = app.add_option("--case", p.initial_case, "a case file to load at start")->envname("DEM_CASE");
  app.add_flag("--run-and-exit", o.run_programme,
               "one-shot: run the case's loading programme (its stages), publishing telemetry and answering "
               "commands meanwhile; write the tables and <out>/<case>/final.snapshot (after a failure "
               "last_good.snapshot) and exit: 0 done, 1 failed, 4 stopped before its end")
      ->needs(p.case_option)
      ->envname("DEM_RUN_AND_EXIT");
  app.add_option("-t,--threads", p.threads, "engine threads, 0 = all cores (default: the case's numerics.threads)")
      ->check(CLI::NonNegativeNumber)
      ->envname("DEM_THREADS");
  app.add_option("--read-dir", o.read_directories,
                 "a directory load_case may read cases (and cases their particle files) from; repeat for more "
                 "(default: none - clients send their cases; the --case file's own load reads its directory)")
      ->envname("DEM_READ_DIRS")
      ->delimiter(':');
  app.add_option("--load-seconds", p.load_seconds,
                 "a case or snapshot still preparing after this many seconds is abandoned with an error")
      ->capture_default_str()
      ->check(CLI::PositiveNumber)
      ->envname("DEM_LOAD_SECONDS");
}

// What it writes: tables, ParaView files, checkpoints.
void add_output(CLI::App& app, Parsed& p) {
  ServerOptions& o = p.line.options;
  app.add_option("-o,--out", o.output_directory, "output directory: CSV tables per case, and snapshots")
      ->capture_default_str()
      ->envname("DEM_OUT");
  app.add_flag("--no-csv", p.no_csv, "write no CSV tables");
  p.vtk_option = app.add_option("--vtk-interval", p.vtk_interval,
                                "cycles between the ParaView files (particles.pvd, contacts.pvd, walls.pvd, vtk/) "
                                "of the programmes it runs; 0 = none (default: each case's output.vtk_interval)")
                     ->check(CLI::NonNegativeNumber)
                     ->envname("DEM_VTK_INTERVAL");
  p.checkpoint_cycles =
      app.add_option("--checkpoint-cycles", o.checkpoints.cycles,
                     "write a checkpoint to <out>/<case>/checkpoints every N cycles (0: none); without this or "
                     "--checkpoint-seconds, programmes (--run-and-exit, run_programme) write a first one 5 s into "
                     "the run and then one every 300 s, cycle and run_until none")
          ->envname("DEM_CHECKPOINT_CYCLES");
  p.checkpoint_seconds = app.add_option("--checkpoint-seconds", o.checkpoints.seconds,
                                        "write a checkpoint every S seconds of wall time (0: none)")
                             ->check(CLI::NonNegativeNumber)
                             ->envname("DEM_CHECKPOINT_SECONDS");
  app.add_option("--checkpoint-keep", o.checkpoints.keep, "checkpoints kept (the newest)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber)
      ->envname("DEM_CHECKPOINT_KEEP");
  app.add_flag("--resume", o.resume,
               "continue the --case from its newest checkpoint in <out>/<case>/checkpoints, appending to its tables "
               "(with --run-and-exit: from where its programme stood)")
      ->needs(p.case_option)
      ->envname("DEM_RESUME");
  app.add_flag("--overwrite", o.overwrite,
               "replace the output of an earlier run in <out>/<case>/ (its tables, snapshots and checkpoints) when "
               "a case is loaded afresh; without it such a load is refused, so nothing is cut unasked")
      ->excludes("--resume")
      ->envname("DEM_OVERWRITE");
}

// What one client may ask of it (docs/RELIABILITY.md, "Limits").
void add_limits(CLI::App& app, Parsed& p) {
  ServerOptions& o = p.line.options;
  app.add_option("--queue-capacity", o.queue_capacity,
                 "commands waiting for the engine; beyond them a command is answered busy")
      ->capture_default_str()
      ->check(CLI::PositiveNumber)
      ->envname("DEM_QUEUE_CAPACITY");
  app.add_option("--max-particles", o.max_particles,
                 "particles one case or snapshot may hold (0: as many as the memory budget holds)")
      ->capture_default_str()
      ->envname("DEM_MAX_PARTICLES");
  app.add_option("--memory-budget", o.memory_budget_bytes,
                 "bytes one world may need, at 2.5 kB a particle (0: half the machine's memory)")
      ->capture_default_str()
      ->envname("DEM_MEMORY_BUDGET");
  app.add_option("--max-cycles", o.limits.max_cycles, "cycles one command may run")
      ->capture_default_str()
      ->check(CLI::PositiveNumber)
      ->envname("DEM_MAX_CYCLES");
  app.add_option("--max-payload-bytes", o.limits.max_payload_bytes,
                 "bytes of case text, case or snapshot one command may carry")
      ->capture_default_str()
      ->check(CLI::PositiveNumber)
      ->envname("DEM_MAX_PAYLOAD_BYTES");
  app.add_option("--max-query-contacts", o.limits.max_query_contacts, "contacts one query may return")
      ->capture_default_str()
      ->check(CLI::PositiveNumber)
      ->envname("DEM_MAX_QUERY_CONTACTS");
}

// The parsed values into ServerOptions; an exit code for one that is wrong
// in a way the parser cannot see.
std::variant<ServerCommandLine, int> finish(Parsed& p) {
  ServerOptions& o = p.line.options;
  if (!protocol::valid_server_name(o.name)) {
    std::cerr << "error: --name \"" << o.name
              << "\" must be a ROS 2 name token: a letter, then letters, digits or underscores\n";
    return kServerBadArguments;
  }
  if (!p.initial_case.empty()) o.initial_case = p.initial_case;
  if (p.threads >= 0) {
    if (const auto problem = io::thread_count_problem(p.threads, io::machine_limits())) {
      std::cerr << "error: --threads " << *problem << '\n';
      return kServerBadArguments;
    }
    o.threads = p.threads;
  }
  // Asked for, checkpoints are the same for every run (both 0: none at all);
  // otherwise programmes keep their default.
  if (p.checkpoint_cycles->count() > 0 || p.checkpoint_seconds->count() > 0) {
    o.programme_checkpoints = o.checkpoints;
  }
  o.programme_checkpoints.keep = o.checkpoints.keep;
  o.record_csv = !p.no_csv;
  if (p.vtk_option->count() > 0) o.vtk_interval = p.vtk_interval;
  o.load_time_limit = std::chrono::seconds(p.load_seconds);
  o.name_wait = std::chrono::milliseconds(static_cast<std::int64_t>(p.name_wait * 1000));
  return std::move(p.line);
}

}  // namespace

std::variant<ServerCommandLine, int> parse_server_command_line(int argc, char** argv) {
  CLI::App app{
      "Runs one DEM simulation as a service on Cyclone DDS (loopback by default), driven by commands and "
      "publishing plate forces, contact statistics and its status."};
  app.set_version_flag("--version", "dem_server " DEM_VERSION);
  Parsed p;
  add_identity(app, p);
  add_case(app, p);
  add_output(app, p);
  add_limits(app, p);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? kServerDone : kServerBadArguments;
  }
  return finish(p);
}

}  // namespace dem::service
