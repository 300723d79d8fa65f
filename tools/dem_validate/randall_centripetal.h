// Randall (1989) 6.4.2, the preliminary tests: an assembly pulled together
// without friction by a centripetal gravity field, bounded, given its
// friction once the field is removed, brought to an isotropic 100 kPa and
// sheared with the mean stress held constant, measured in three circles
// that hold 15, 34 and 62 % of the particles (cases/randall/centripetal*).
// Runs the case's stages "compact", the "bound_..." walls, "friction",
// "load" and "shear", and measures what 6.4.2 reports: the forces largest
// at the centre after the compaction (Fig. 6.4), the assembly denser in the
// centre (Fig. 6.5), the quasi-equilibrium at 100 kPa (Fig. 6.6), sin(phi)
// (Fig. 6.7) and the volumetric strain (Fig. 6.8) of each circle against
// its deviator strain, the strains from each circle's best-fit displacement
// gradient (dem/analysis/region_strain.h).
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dem/analysis/region_measures.h"
#include "dem/analysis/region_strain.h"
#include "verdict.h"

namespace dem::validation {

// One circle at one moment of the shear.
struct CircleSample {
  analysis::RegionMeasures measures;
  analysis::RegionStrain strain;  // since the shear began (the assembly at 100 kPa)
};

struct CentripetalSample {
  std::uint64_t cycle = 0;
  double deviator_strain = 0.0;  // the box's
  double out_of_balance = 0.0;   // Delta F / F
  std::vector<CircleSample> circles;
};

// What a circle holds at one state of the preparation.
struct CircleState {
  std::string name;
  double radius = 0.0;  // m
  double share = 0.0;   // of all the particles, by centre
  double porosity = 0.0;
  double mean_stress = 0.0;  // Pa
  double hydrostatic = 0.0;  // Pa: the field's hydrostatic stress averaged over the circle (after compaction only)
  double mean_normal_force = 0.0;  // N
  double coordination = 0.0;
};

struct CentripetalRun {
  std::string name;
  std::uint64_t packing_seed = 0;
  int particles = 0;
  std::uint64_t cycles = 0;
  double seconds = 0.0;
  bool settled = false;                    // the compaction, friction and load stages met their conditions
  double acceleration = 0.0;               // m/s^2, the field
  double disc_radius = 0.0;                // m: the disc the particles would fill at the largest circle's density
  std::vector<CircleState> compacted;      // at the end of the compaction, in the field (Fig. 6.4)
  std::vector<CircleState> settled_state;  // the field removed, friction added, at equilibrium (Fig. 6.5)
  std::vector<CircleState> at_100_kpa;     // (Fig. 6.6)
  double box_stress = 0.0;      // Pa, the box control's mean at 100 kPa (over its extents: 0.414 of the walls')
  double out_of_balance = 0.0;  // Delta F / F at 100 kPa
  std::vector<CentripetalSample> shear;
};

// Runs the case (on its own packing or on `packing_seed`'s); with `out`,
// writes centripetal.csv (each circle through the shear: its measures and
// its strain), circles.csv (their centres and radii), profile.csv (porosity and contact force by radius, after
// the compaction and at equilibrium) and the contacts and particles after
// the compaction, at 100 kPa and at the end of the shear.
CentripetalRun run_centripetal(const std::filesystem::path& case_file,
                               const std::optional<std::filesystem::path>& out = std::nullopt,
                               std::optional<std::uint64_t> packing_seed = std::nullopt);

void print_centripetal(std::FILE* out, const CentripetalRun& run);

// The figures 6.4.2 is judged on, of one packing or the median over several.
struct CentripetalMeasured {
  std::string label;
  bool settled = false;
  double share_small = 0.0, share_middle = 0.0, share_large = 0.0;  // "15, 34 and 62%"
  // Fig. 6.4: the mean stress in the field, in the smallest circle over
  // the largest, and each circle's against the field's hydrostatic stress.
  double compaction_stress_ratio = 0.0;
  double worst_hydrostatic_ratio = 0.0;  // the circle furthest from it: measured / hydrostatic
  // Fig. 6.5: porosity of the smallest and the largest circle at equilibrium.
  double porosity_small = 0.0, porosity_large = 0.0;
  // Fig. 6.6: the largest circle's mean stress at 100 kPa, Delta F / F.
  double interior_stress = 0.0;
  double out_of_balance = 0.0;
  bool sheared = false;
  double final_deviator = 0.0;  // the largest circle's deviator strain at the end
  // Fig. 6.7: the largest difference of the circles' sin(phi) once the
  // largest has 0.5 % deviator strain, and each circle's peak.
  double sin_phi_spread = 0.0;
  double peak_sin_phi = 0.0;  // the largest circle's
  // Fig. 6.8: each circle's largest contraction (volumetric strain,
  // contraction positive) and the deviator strain where it turns to
  // expand; the expansion from there to the end.
  double contraction_small = 0.0, contraction_large = 0.0;
  double turn_small = 0.0, turn_large = 0.0;
  double expansion_small = 0.0, expansion_large = 0.0;
  double late_expansion_large = 0.0;  // over the last quarter of the shear
  // At the end: the smallest circle's volumetric strain less the largest's
  // (negative: the centre has expanded more).
  double end_volumetric_difference = 0.0;
  double mean_stress_drift = 0.0;  // the largest circle's mean stress at the end over at the start
};

CentripetalMeasured measure_centripetal(const CentripetalRun& run);
CentripetalMeasured median_of(const std::vector<CentripetalMeasured>& packings);
void print_packings(std::FILE* out, const std::vector<CentripetalMeasured>& packings);

// What 6.4.2 states, with the tolerances: the circles' shares within 3
// points, the forces falling from the centre (and the field's hydrostatic
// stress within 20 %), denser at the centre, 100 kPa within 10 % and
// Delta F / F < 0.1, sin(phi) of the three circles within 0.05 of each
// other, the largest circle contracting then expanding from 0.25-1 % ("at
// around 0.5%") to the end, the smallest expanding from the start (turning
// by 0.1 %) and more than the largest by the end.
Verdict judge_centripetal(const CentripetalMeasured& measured);

// Runs the case on each seed (its own packing when `seeds` is empty), into
// out/packing_<seed>/ when there are several, prints each run and the
// packings' table, and judges the median.
Verdict report_centripetal(const std::filesystem::path& case_file, const std::optional<std::filesystem::path>& out,
                           const std::vector<std::uint64_t>& seeds);

}  // namespace dem::validation
