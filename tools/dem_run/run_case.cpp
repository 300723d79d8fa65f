#include "run_case.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>
#include <variant>

#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/io/snapshot_file.h"
#include "dem/programme.h"
#include "dem/world.h"
#include "interrupt.h"
#include "progress_line.h"
#include "run_recorder.h"
#include "run_summary.h"

namespace dem::run {
namespace {

// The run itself, once per dimension.
template <int Dim>
RunOutcome run_definition(io::CaseDefinitionT<Dim>& definition, const io::CaseSource& source,
                          const RunOptions& options) {
  if (definition.stages.empty()) {
    throw io::CaseError(
        io::describe_problem(source, "stage", "the case defines no stages, so there is nothing to run"));
  }
  if (options.threads) definition.world.threads = *options.threads;
  if (options.vtk_interval) definition.output.vtk_interval = *options.vtk_interval;

  BasicWorld<Dim> world(definition.world);
  RunRecorder<Dim> recorder(options.output_directory, definition.output, world);
  ProgressLine progress(!options.quiet && isatty(fileno(stderr)) == 1);
  const bool summary = !options.quiet;
  if (summary) print_case_header(std::cout, definition, world);

  recorder.record(world, 0);
  const auto stage_count = static_cast<int>(definition.stages.size());
  const std::uint64_t interval = std::max<std::uint64_t>(definition.output.interval, 1);
  for (int i = 0; i < stage_count && !interrupted(); ++i) {
    const StageDefT<Dim>& stage = definition.stages[i];
    const std::uint64_t start = world.cycle_count();
    // Observed every cycle, so Ctrl-C is answered at once; a row every
    // output interval counted from the stage's start (as run_stage counts).
    const StageResult result = run_stage(world, stage, 1, [&](const BasicWorld<Dim>& w) {
      const std::uint64_t done = w.cycle_count() - start;
      if (done % interval == 0) recorder.record(w, i);
      progress.show(i, stage_count, stage, done, w);
      return !interrupted();
    });
    recorder.record(world, i);
    progress.clear();
    if (interrupted()) {
      std::cerr << "interrupted in stage " << i + 1 << '/' << stage_count << " at cycle " << world.cycle_count()
                << ": writing the tables and the snapshot of the state reached\n";
    } else if (summary) {
      print_stage_result(std::cout, i, stage_count, stage, result);
    }
  }
  recorder.finish(world);
  const std::filesystem::path snapshot = options.output_directory / "final.snapshot";
  io::write_snapshot_file(snapshot, world.snapshot(), io::SnapshotInfo{definition.name, definition.description});
  std::vector<std::filesystem::path> files = recorder.files();
  files.push_back(snapshot);
  if (summary) print_final_state(std::cout, world, files);
  return interrupted() ? RunOutcome::kInterrupted : RunOutcome::kCompleted;
}

}  // namespace

RunOutcome run_case(const RunOptions& options) {
  const io::LoadedCase loaded = io::load_case_file(options.case_path);
  io::AnyCaseDefinition definition = io::convert_any_case(loaded.message, loaded.source);
  watch_interrupts();
  return std::visit([&](auto& def) { return run_definition(def, loaded.source, options); }, definition);
}

}  // namespace dem::run
