#include "run_case.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>
#include <variant>

#include "dem/cli/interrupt.h"
#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/io/earlier_run.h"
#include "dem/io/snapshot_file.h"
#include "dem/io/world_checks.h"
#include "dem/law_traits.h"
#include "dem/programme.h"
#include "dem/world.h"
#include "progress_line.h"
#include "run_checkpoints.h"
#include "run_health.h"
#include "run_recorder.h"
#include "run_summary.h"

namespace dem::run {
namespace {

// Writes the last good state beside the tables and throws RunFailure.
template <int Dim>
[[noreturn]] void fail(const RunHealth<Dim>& health, const io::CaseDefinitionT<Dim>& definition,
                       const RunOptions& options, int stage, const StepHealth& problem) {
  const std::filesystem::path path = options.output_directory / "last_good.snapshot";
  io::write_snapshot_file(path, health.last_good(), io::SnapshotInfo{definition.name, definition.description});
  throw RunFailure("the run is unhealthy in stage " + std::to_string(stage + 1) + " (" +
                   definition.stages[static_cast<std::size_t>(stage)].name + ") " + problem.message +
                   "\nthe last good state, at cycle " + std::to_string(health.last_good().cycle) + ", is in " +
                   path.string());
}

// The newest checkpoint in the output directory, as a world and where it stood.
template <int Dim>
std::pair<BasicWorld<Dim>, io::ResumePoint> resume_from(const RunOptions& options, const std::string& digest,
                                                        std::size_t stage_count) {
  const io::CheckpointStore store(options.output_directory / "checkpoints", options.checkpoints.keep);
  std::optional<io::CheckpointStore::Latest> latest = store.latest();
  if (!latest) {
    throw std::runtime_error("--resume: no whole checkpoint in " + store.directory().string() +
                             " (run without --resume to start afresh)");
  }
  if (latest->point.case_digest != digest) {
    throw std::runtime_error("--resume: " + latest->path.string() +
                             " belongs to another case (or this one changed "
                             "since): run it without --resume into a fresh directory");
  }
  if (latest->point.stage >= stage_count)
    throw std::runtime_error("--resume: the checkpoint's stage is past the case's");
  BasicWorld<Dim> world(io::parse_snapshot<Dim>(latest->snapshot_bytes, latest->path.string()).snapshot);
  return {std::move(world), std::move(latest->point)};
}

// The run itself, once per dimension.
template <int Dim>
RunOutcome run_definition(io::CaseDefinitionT<Dim>& definition, const io::CaseSource& source, const RunOptions& options,
                          const std::string& digest) {
  if (definition.stages.empty()) {
    throw io::CaseError(
        io::describe_problem(source, "stage", "the case defines no stages, so there is nothing to run"));
  }
  if (options.threads) definition.world.threads = *options.threads;
  if (options.vtk_interval) definition.output.vtk_interval = *options.vtk_interval;

  std::optional<BasicWorld<Dim>> built;
  std::optional<io::ResumePoint> resumed;
  if (options.resume) {
    auto [world, point] = resume_from<Dim>(options, digest, definition.stages.size());
    built.emplace(std::move(world));
    resumed = std::move(point);
    if (options.threads) built->set_threads(*options.threads);
  } else {
    built.emplace(definition.world);
    io::check_built_world(*built, definition.stages, source);
  }
  BasicWorld<Dim>& world = *built;
  RunHealth<Dim> health(world);
  const bool hertz =
      std::ranges::any_of(definition.world.contact_models, [](const ContactModelDef& m) { return is_hertz(m.law); });
  RunRecorder<Dim> recorder(options.output_directory, definition.output, world, hertz, resumed ? &*resumed : nullptr);
  RunCheckpoints<Dim> checkpoints(options.output_directory, options.checkpoints, digest, world.cycle_count());
  const io::SnapshotInfo info{definition.name, definition.description};
  ProgressLine progress(!options.quiet && isatty(fileno(stderr)) == 1);
  const bool summary = !options.quiet;
  if (summary) print_case_header(std::cout, definition, world);
  if (summary && resumed) {
    std::cout << "resumed from the checkpoint at cycle " << resumed->cycle << " (stage " << resumed->stage + 1 << ", "
              << resumed->stage_cycles << " cycles into it)\n";
  }

  if (!resumed) recorder.record(world, 0);
  const auto stage_count = static_cast<int>(definition.stages.size());
  const std::uint64_t interval = std::max<std::uint64_t>(definition.output.interval, 1);
  for (int i = resumed ? static_cast<int>(resumed->stage) : 0; i < stage_count && !cli::interrupted(); ++i) {
    const std::uint64_t done_before = resumed && i == static_cast<int>(resumed->stage) ? resumed->stage_cycles : 0;
    const StageDefT<Dim>& stage = definition.stages[i];
    const StageDefT<Dim> running = done_before > 0 ? stage_remainder(stage, done_before) : stage;
    const std::uint64_t start = world.cycle_count() - done_before;
    std::optional<StepHealth> problem;
    // Observed every cycle, so Ctrl-C is answered at once; a row every
    // output interval counted from the stage's start (as run_stage counts).
    StageResult result = run_stage(world, running, 1, [&](const BasicWorld<Dim>& w) {
      const std::uint64_t done = w.cycle_count() - start;
      const bool row = done % interval == 0;
      // Nothing is recorded of an unhealthy state. The check is paced; at a
      // row, a blow-up's motion brings it at once.
      if ((problem = health.check(w, row && health.suspect(w)))) return false;
      if (row) {
        recorder.record(w, i);
        if (checkpoints.due(w, stage, done)) {
          // Only a state found healthy is kept.
          if ((problem = health.check(w, true))) return false;
          checkpoints.write(w, info, recorder, static_cast<std::size_t>(i), done);
        }
      }
      progress.show(i, stage_count, stage, done, w);
      return !cli::interrupted();
    });
    result.cycles_run += done_before;
    progress.clear();
    if (!problem) problem = health.check(world, true);
    if (problem) fail(health, definition, options, i, *problem);
    recorder.record(world, i);
    if (cli::interrupted()) {
      std::cerr << "interrupted in stage " << i + 1 << '/' << stage_count << " at cycle " << world.cycle_count()
                << ": writing the tables and the snapshot of the state reached\n";
    } else if (summary) {
      print_stage_result(std::cout, i, stage_count, stage, result);
    }
  }
  recorder.finish(world);
  const std::filesystem::path snapshot = options.output_directory / "final.snapshot";
  io::write_snapshot_file(snapshot, world.snapshot(), info);
  std::vector<std::filesystem::path> files = recorder.files();
  files.push_back(snapshot);
  if (summary) print_final_state(std::cout, world, files);
  return cli::interrupted() ? RunOutcome::kInterrupted : RunOutcome::kCompleted;
}

// A fresh run into a directory that holds an earlier run's outputs would
// cut its tables: refused unless --overwrite, which removes them first (and
// only them: --out is the user's directory and may hold other files).
void claim_output(const RunOptions& options) {
  if (options.resume) return;
  const std::vector<std::string> names = io::earlier_run_entries(options.output_directory, io::RunEntries::kWritten);
  if (names.empty()) return;
  if (!options.overwrite) {
    throw OutputInUse(options.output_directory.string() + " holds the output of an earlier run (" +
                      io::some_names(names) +
                      "), which a new run would cut: continue it with --resume, replace it with --overwrite, or give "
                      "another --out");
  }
  io::remove_entries(options.output_directory, names);
}

}  // namespace

RunOutcome run_case(const RunOptions& options) {
  const io::LoadedCase loaded = io::load_case_file(options.case_path);
  io::AnyCaseDefinition definition = io::convert_any_case(loaded.message, loaded.source);
  claim_output(options);
  const std::string digest = io::file_digest(options.case_path);
  cli::watch_interrupts();
  return std::visit([&](auto& def) { return run_definition(def, loaded.source, options, digest); }, definition);
}

}  // namespace dem::run
