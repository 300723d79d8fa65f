#include "run_case.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <string>

#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/programme.h"
#include "dem/world.h"
#include "progress_line.h"
#include "run_recorder.h"
#include "run_summary.h"

namespace dem::run {

void run_case(const RunOptions& options) {
  const io::LoadedCase loaded = io::load_case_file(options.case_path);
  io::CaseDefinition definition = io::convert_case(loaded.message, loaded.source);
  if (definition.stages.empty()) {
    throw io::CaseError(
        io::describe_problem(loaded.source, "stage", "the case defines no stages, so there is nothing to run"));
  }
  if (options.threads) definition.world.threads = *options.threads;

  World world(definition.world);
  RunRecorder recorder(options.output_directory, definition.output);
  ProgressLine progress(!options.quiet && isatty(fileno(stderr)) == 1);
  const bool summary = !options.quiet;
  if (summary) print_case_header(std::cout, definition, world);

  recorder.record(world);
  const auto stage_count = static_cast<int>(definition.stages.size());
  for (int i = 0; i < stage_count; ++i) {
    const StageDef& stage = definition.stages[i];
    const std::uint64_t start = world.cycle_count();
    const StageResult result = run_stage(world, stage, definition.output.interval, [&](const World& w) {
      recorder.record(w);
      progress.show(i, stage_count, stage, w.cycle_count() - start, w);
      return true;
    });
    recorder.record(world);
    progress.clear();
    if (summary) print_stage_result(std::cout, i, stage_count, stage, result);
  }
  recorder.finish(world);
  if (summary) print_final_state(std::cout, world, recorder.files());
}

}  // namespace dem::run
