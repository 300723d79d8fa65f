#include "run_case.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <string>
#include <variant>

#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/io/snapshot_file.h"
#include "dem/io/world_checks.h"
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

// The rest of a stage a checkpoint interrupted: its start actions (trim,
// placing a wall, motions, damping) are done and in the state; its length
// and minimum count from where it stood.
template <int Dim>
StageDefT<Dim> remainder(StageDefT<Dim> stage, std::uint64_t done) {
  stage.trim.reset();
  stage.place_wall.reset();
  stage.wall_motions.clear();
  stage.damping.reset();
  stage.cycles -= done;
  stage.until.min_cycles = stage.until.min_cycles > done ? stage.until.min_cycles - done : 0;
  return stage;
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
    throw std::runtime_error("--resume: " + latest->path.string() + " belongs to another case (or this one changed "
                             "since): run it without --resume into a fresh directory");
  }
  if (latest->point.stage >= stage_count) throw std::runtime_error("--resume: the checkpoint's stage is past the case's");
  BasicWorld<Dim> world(io::parse_snapshot<Dim>(latest->snapshot_bytes, latest->path.string()).snapshot);
  return {std::move(world), std::move(latest->point)};
}

// The run itself, once per dimension.
template <int Dim>
void run_definition(io::CaseDefinitionT<Dim>& definition, const io::CaseSource& source, const RunOptions& options,
                    const std::string& digest) {
  if (definition.stages.empty()) {
    throw io::CaseError(
        io::describe_problem(source, "stage", "the case defines no stages, so there is nothing to run"));
  }
  if (options.threads) definition.world.threads = *options.threads;

  std::optional<BasicWorld<Dim>> built;
  std::optional<io::ResumePoint> resumed;
  if (options.resume) {
    auto [world, point] = resume_from<Dim>(options, digest, definition.stages.size());
    built.emplace(std::move(world));
    resumed = std::move(point);
    if (options.threads) built->set_threads(*options.threads);
  } else {
    built.emplace(definition.world);
    io::check_built_world(*built, source);
  }
  BasicWorld<Dim>& world = *built;
  RunHealth<Dim> health(world);
  RunRecorder<Dim> recorder(options.output_directory, definition.output, world, resumed ? &*resumed : nullptr);
  RunCheckpoints<Dim> checkpoints(options.output_directory, options.checkpoints, digest, world.cycle_count());
  const io::SnapshotInfo info{definition.name, definition.description};
  ProgressLine progress(!options.quiet && isatty(fileno(stderr)) == 1);
  const bool summary = !options.quiet;
  if (summary) print_case_header(std::cout, definition, world);
  if (summary && resumed) {
    std::cout << "resumed from the checkpoint at cycle " << resumed->cycle << " (stage " << resumed->stage + 1
              << ", " << resumed->stage_cycles << " cycles into it)\n";
  }

  if (!resumed) recorder.record(world, 0);
  const auto stage_count = static_cast<int>(definition.stages.size());
  for (int i = resumed ? static_cast<int>(resumed->stage) : 0; i < stage_count; ++i) {
    const std::uint64_t done = resumed && i == static_cast<int>(resumed->stage) ? resumed->stage_cycles : 0;
    const StageDefT<Dim>& stage = definition.stages[i];
    const StageDefT<Dim> running = done > 0 ? remainder(stage, done) : stage;
    const std::uint64_t start = world.cycle_count() - done;
    std::optional<StepHealth> problem;
    StageResult result = run_stage(world, running, definition.output.interval, [&](const BasicWorld<Dim>& w) {
      // Nothing is recorded of an unhealthy state.
      if ((problem = health.check(w))) return false;
      recorder.record(w, i);
      progress.show(i, stage_count, stage, w.cycle_count() - start, w);
      const std::uint64_t stage_cycles = w.cycle_count() - start;
      if (checkpoints.due(w, stage, stage_cycles)) {
        // Only a state found healthy is kept.
        if ((problem = health.check(w, true))) return false;
        checkpoints.write(w, info, recorder, static_cast<std::size_t>(i), stage_cycles);
      }
      return true;
    });
    result.cycles_run += done;
    progress.clear();
    if (!problem) problem = health.check(world, true);
    if (problem) fail(health, definition, options, i, *problem);
    recorder.record(world, i);
    if (summary) print_stage_result(std::cout, i, stage_count, stage, result);
  }
  recorder.finish(world);
  if (summary) print_final_state(std::cout, world, recorder.files());
}

}  // namespace

void run_case(const RunOptions& options) {
  const io::LoadedCase loaded = io::load_case_file(options.case_path);
  io::AnyCaseDefinition definition = io::convert_any_case(loaded.message, loaded.source);
  const std::string digest = io::file_digest(options.case_path);
  std::visit([&](auto& def) { run_definition(def, loaded.source, options, digest); }, definition);
}

}  // namespace dem::run
