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

template <int Dim>
void print_case_header(std::ostream& out, const io::CaseDefinitionT<Dim>& definition, const BasicWorld<Dim>& world);
template <int Dim>
void print_stage_result(std::ostream& out, int stage_index, int stage_count, const StageDefT<Dim>& stage,
                        const StageResult& result);
template <int Dim>
void print_final_state(std::ostream& out, const BasicWorld<Dim>& world,
                       const std::vector<std::filesystem::path>& files);

}  // namespace dem::run
