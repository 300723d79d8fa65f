// dem_run CASE --out DIR [--threads N] [--vtk-interval N] [--quiet]: runs a 2D or 3D case.
//        [--checkpoint-cycles N] [--checkpoint-seconds S] [--checkpoint-keep K] [--resume | --overwrite]
// Exit codes: 0 done; 1 a run that became numerically unhealthy (its last
// good state is in DIR/last_good.snapshot) or any other failure (for
// example an unwritable output directory); 2 bad command-line arguments, or
// DIR holding an earlier run's output without --resume or --overwrite;
// 3 a case that cannot be read, parsed, validated or built (the message
// names the file and the field); 130 interrupted (Ctrl-C or SIGTERM),
// after writing the state reached.
#include <CLI/CLI.hpp>
#include <exception>
#include <functional>
#include <iostream>
#include <string>

#include "dem/error.h"
#include "dem/io/case_error.h"
#include "dem/io/resource_limits.h"
#include "dem/version.h"
#include "run_case.h"

namespace {

constexpr int kFailure = 1;
constexpr int kBadArguments = 2;
constexpr int kBadCase = 3;
constexpr int kInterrupted = 130;  // as a shell reports a program Ctrl-C ended

// CLI11's NonNegativeNumber would print its upper bound, DBL_MAX, in full;
// and an unsigned option would take "-5" as a huge number.
std::function<std::string(const std::string&)> whole_number(std::string meaning) {
  return [meaning = std::move(meaning)](const std::string& text) -> std::string {
    if (!text.empty() && text.find_first_not_of("0123456789") == std::string::npos) return {};
    return "must be a whole number >= 0 (" + meaning + "), got " + text;
  };
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Runs a DEM case headless and writes its results as CSV files, a final snapshot and, when asked, "
      "ParaView files."};
  app.set_version_flag("--version", "dem_run " DEM_VERSION);
  app.footer(
      "Exit codes: 0 done, 1 other failure, 2 bad arguments (or OUT holds an earlier run: --resume or --overwrite), 3 "
      "an invalid case (file, line and field named),\n"
      "130 interrupted (Ctrl-C): the tables and final.snapshot hold the state reached.");
  dem::run::RunOptions options;
  int threads = 0;
  app.add_option("case", options.case_path, "case file in protobuf text format")->required();
  app.add_option("-o,--out", options.output_directory, "directory for the CSV files (created if missing)")->required();
  const CLI::Option* threads_option =
      app.add_option("-t,--threads", threads, "worker threads, 0 = all cores (default: the case's numerics.threads)")
          ->check(whole_number("0 = all cores"));
  std::uint64_t vtk_interval = 0;
  const CLI::Option* vtk_option = app.add_option("--vtk-interval", vtk_interval,
                                                 "cycles between ParaView files (particles.pvd, contacts.pvd, "
                                                 "walls.pvd and vtk/); 0 = none (default: the case's "
                                                 "output.vtk_interval)")
                                      ->check(whole_number("0 = none"));
  app.add_flag("-q,--quiet", options.quiet, "print errors only: no progress line and no summary");
  const CLI::Option* checkpoint_cycles =
      app.add_option("--checkpoint-cycles", options.checkpoints.cycles,
                     "write a checkpoint to OUT/checkpoints every N cycles (0: none); without this or "
                     "--checkpoint-seconds, a first one 5 s into the run and then one every 300 s");
  const CLI::Option* checkpoint_seconds = app.add_option("--checkpoint-seconds", options.checkpoints.seconds,
                                                         "write a checkpoint every S seconds of wall time (0: none)")
                                              ->check(CLI::NonNegativeNumber);
  app.add_option("--checkpoint-keep", options.checkpoints.keep, "checkpoints kept (the newest)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  CLI::Option* resume = app.add_flag("--resume", options.resume,
                                     "continue from the newest checkpoint in OUT/checkpoints, appending to its tables");
  app.add_flag("--overwrite", options.overwrite,
               "start afresh even though OUT holds an earlier run's output: its tables (.csv), snapshots, ParaView "
               "files (.pvd, vtk/) and checkpoints are removed first; without it such a run is refused (exit 2)")
      ->excludes(resume);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help arrives here too, and is not a mistake.
    return app.exit(error) == 0 ? 0 : kBadArguments;
  }
  // A programme run checkpoints unless told otherwise (both 0: none).
  if (checkpoint_cycles->count() == 0 && checkpoint_seconds->count() == 0) {
    const int keep = options.checkpoints.keep;
    options.checkpoints = dem::io::default_programme_checkpoints();
    options.checkpoints.keep = keep;
  }
  if (threads_option->count() > 0) {
    if (const auto problem = dem::io::thread_count_problem(threads, dem::io::machine_limits())) {
      std::cerr << "error: --threads " << *problem << '\n';
      return kBadArguments;
    }
    options.threads = threads;
  }
  if (vtk_option->count() > 0) options.vtk_interval = vtk_interval;

  try {
    return dem::run::run_case(options) == dem::run::RunOutcome::kCompleted ? 0 : kInterrupted;
  } catch (const dem::run::OutputInUse& error) {
    std::cerr << "error: " << error.what() << '\n';
    return kBadArguments;
  } catch (const dem::io::CaseError& error) {
    for (const auto& problem : error.problems()) std::cerr << "error: " << problem << '\n';
    return kBadCase;
  } catch (const dem::DefinitionError& error) {
    std::cerr << "error: " << options.case_path.string() << ": " << error.what() << '\n';
    return kBadCase;
  } catch (const std::exception& error) {
    std::cerr << "error: " << error.what() << '\n';
    return kFailure;
  }
}
