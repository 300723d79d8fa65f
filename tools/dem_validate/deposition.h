// Randall (1989) 6.3: Webster's pluvial deposition
// (cases/randall/pluvial_deposition.case.txtpb): spheres rain into a
// container at the Rayleigh step and settle at a smaller one. What the
// thesis reports is qualitative (arches forming and collapsing at the
// corners; a step too large near equilibrium); what the run can be held
// to: the bed comes to rest, the container carries its weight, and
// Randall's particle-wise step check (4.35-4.40) as the rain lands and as
// the bed settles.
#pragma once

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "dem/analysis/region_measures.h"
#include "verdict.h"

namespace dem::validation {

struct DepositionRun {
  std::string name;
  int particles = 0;
  std::uint64_t cycles = 0;
  double seconds = 0.0;
  bool at_rest = false;            // the settle stage met its condition
  double weight = 0.0;             // N (spheres in the plane: their own weight)
  double walls_vertical = 0.0;     // N: the vertical force the container's walls carry
  double rain_step_ratio = 0.0;    // the largest dt over the particle-wise critical step while it rains
  double settle_step_ratio = 0.0;  // and while it settles (at the smaller step)
  analysis::RegionMeasures bed;    // the case's first region at the end
};

DepositionRun run_deposition(const std::filesystem::path& case_file,
                             const std::optional<std::filesystem::path>& out = std::nullopt);
void print_deposition(std::FILE* out, const DepositionRun& run);
Verdict judge_deposition(const DepositionRun& run);

}  // namespace dem::validation
