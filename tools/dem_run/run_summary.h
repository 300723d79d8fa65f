// What dem_run tells the user: the case and its time step before the run,
// a line per stage as it ends, the final wall forces and balance after.
#pragma once

#include <filesystem>
#include <ostream>
#include <vector>

#include "dem/io/case_definition.h"
#include "dem/programme.h"
#include "dem/world.h"

namespace dem::run {

void print_case_header(std::ostream& out, const io::CaseDefinition& definition, const World& world);
void print_stage_result(std::ostream& out, int stage_index, int stage_count, const StageDef& stage,
                        const StageResult& result);
void print_final_state(std::ostream& out, const World& world, const std::vector<std::filesystem::path>& files);

}  // namespace dem::run
