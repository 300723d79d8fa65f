// Randall (1989) 6.3: Webster's pluvial deposition
// (cases/randall/pluvial_deposition*.case.txtpb): spheres rain into a
// container at the Rayleigh step and settle at a smaller one. The thesis
// reports "arch formation and collapse at the corners of the container"
// and a step too large near equilibrium. What the run measures: the bed
// comes to rest and the container carries its weight; the arching, as the
// share of the weight the side walls carry by friction rather than the
// floor (Janssen 1895), against Janssen's for the bed's height, stress
// ratio and the walls' full friction; the collapses, as particles that came
// to rest in an arch (two contacts or more) and later dropped by a quarter
// of their radius, in the container's two bottom corners and, for
// comparison, in the middle of its floor; and Randall's particle-wise step
// check (4.35-4.40) as the rain lands and as the bed settles.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dem/analysis/region_measures.h"
#include "verdict.h"

namespace dem::validation {

// Where a collapse is counted: squares as wide as three of the largest
// diameters at the floor's two ends and at its middle.
struct DepositionZones {
  int corner_resting = 0;    // particles that came to rest in a corner square
  int corner_collapses = 0;  // of which later dropped
  int middle_resting = 0;
  int middle_collapses = 0;
  int elsewhere_resting = 0;  // anywhere else in the bed
  int elsewhere_collapses = 0;
};

struct DepositionRun {
  std::string name;
  std::uint64_t packing_seed = 0;
  int particles = 0;
  std::uint64_t cycles = 0;
  double seconds = 0.0;
  bool at_rest = false;            // the settle stage met its condition
  double weight = 0.0;             // N (spheres in the plane: their own weight)
  double walls_vertical = 0.0;     // N: the vertical force the container's walls carry
  double floor_vertical = 0.0;     // N: of which the floor
  double side_normal = 0.0;        // N: the side walls' normal forces, summed
  double width = 0.0;              // m, between the side walls
  double solid_area = 0.0;         // m^2, the spheres' central sections
  double friction_limit = 0.0;     // the smaller of the materials' friction: what the walls can mobilise
  double rain_step_ratio = 0.0;    // the largest dt over the particle-wise critical step while it rains
  double settle_step_ratio = 0.0;  // and while it settles (at the smaller step)
  DepositionZones zones;
  analysis::RegionMeasures bed;  // the case's first region at the end

  double side_share() const { return weight > 0.0 ? (walls_vertical - floor_vertical) / weight : 0.0; }
  // The side walls' mobilised friction: their vertical force over their normal force.
  double wall_friction() const { return side_normal > 0.0 ? (walls_vertical - floor_vertical) / side_normal : 0.0; }
  // The bed's height: its spheres' area over the container's width and the bed's solidity.
  double bed_height() const;
  // Janssen's (1895) share of the weight on the side walls, for the bed's
  // height, its horizontal over vertical stress K and a wall friction mu:
  // 1 - (1 - e^-x) / x, x = 2 mu K H / D; with the friction the walls
  // mobilise, and with all of it (the arching a Janssen bed would show).
  double janssen_side_share(double wall_friction) const;
};

DepositionRun run_deposition(const std::filesystem::path& case_file,
                             const std::optional<std::filesystem::path>& out = std::nullopt,
                             std::optional<std::uint64_t> packing_seed = std::nullopt);
void print_deposition(std::FILE* out, const DepositionRun& run);
// The bed of one packing: at rest, carried, at the settling step.
Verdict judge_deposition(const DepositionRun& run);
// What 6.3 reports, over the packings (it depends on the packing): the
// Rayleigh step too large once the rain lands, arching (the median
// packing's side walls carrying a good part of Janssen's share) and arches
// collapsing in the corners, more than in the middle of the floor.
Verdict judge_deposition_phenomena(const std::vector<DepositionRun>& runs);

// Runs the case on each seed (its own packing when `seeds` is empty), into
// out/packing_<seed>/ when there are several, prints each and judges them.
Verdict report_deposition(const std::filesystem::path& case_file, const std::optional<std::filesystem::path>& out,
                          const std::vector<std::uint64_t>& seeds);

}  // namespace dem::validation
