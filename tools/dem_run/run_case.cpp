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

// The run itself, once per dimension.
template <int Dim>
void run_definition(io::CaseDefinitionT<Dim>& definition, const io::CaseSource& source, const RunOptions& options) {
  if (definition.stages.empty()) {
    throw io::CaseError(
        io::describe_problem(source, "stage", "the case defines no stages, so there is nothing to run"));
  }
  if (options.threads) definition.world.threads = *options.threads;

  BasicWorld<Dim> world(definition.world);
  io::check_built_world(world, source);
  RunHealth<Dim> health(world);
  RunRecorder<Dim> recorder(options.output_directory, definition.output, world);
  ProgressLine progress(!options.quiet && isatty(fileno(stderr)) == 1);
  const bool summary = !options.quiet;
  if (summary) print_case_header(std::cout, definition, world);

  recorder.record(world, 0);
  const auto stage_count = static_cast<int>(definition.stages.size());
  for (int i = 0; i < stage_count; ++i) {
    const StageDefT<Dim>& stage = definition.stages[i];
    const std::uint64_t start = world.cycle_count();
    std::optional<StepHealth> problem;
    const StageResult result = run_stage(world, stage, definition.output.interval, [&](const BasicWorld<Dim>& w) {
      // Nothing is recorded of an unhealthy state.
      if ((problem = health.check(w))) return false;
      recorder.record(w, i);
      progress.show(i, stage_count, stage, w.cycle_count() - start, w);
      return true;
    });
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
  std::visit([&](auto& def) { run_definition(def, loaded.source, options); }, definition);
}

}  // namespace dem::run
