// Randall (1989) 6.4.3 and 6.5.2: a large assembly of spheres in the plane
// compressed to an isotropic 100 kPa without friction, given its friction
// at quasi-equilibrium, and sheared at constant volume; the uniform and the
// graded samples (cases/randall/). Runs a case's stages "compress",
// "friction" and, when asked, "shear", and measures what chapter 6 reports:
// coordination, porosity, F_max / F_mean, the roses of contact normals and
// the obliquities at 100 kPa; sin(phi), the isotropic stress, the stress
// path, the tangential forces' share, the sliding contacts, the structural
// anisotropy and the coordination as the shear goes; the velocity field.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dem/analysis/distributions.h"
#include "dem/analysis/region_measures.h"
#include "verdict.h"

namespace dem::validation {

// The assembly at one moment of the shear.
struct ShearSample {
  std::uint64_t cycle = 0;
  double deviator_strain = 0.0;  // the box's, sigma_y's axis shortened, sigma_x's lengthened
  double volumetric_strain = 0.0;
  double out_of_balance = 0.0;                    // Delta F / F
  std::vector<analysis::RegionMeasures> regions;  // the case's regions, in order
};

struct RandallRun {
  std::string name;
  int particles = 0;
  std::uint64_t cycles = 0;
  double seconds = 0.0;
  double friction = 0.0;    // tan(phi) between the particles after the friction stage
  bool compressed = false;  // the compression and friction stages met their conditions
  // At quasi-equilibrium at 100 kPa with friction (6.4.3), in the case's
  // first region (a measurement circle well inside the walls).
  analysis::RegionMeasures at_rest;
  double box_mean_stress = 0.0;  // Pa
  double out_of_balance = 0.0;
  std::vector<analysis::Bin> rose, weighted_rose, obliquity;  // Figs. 6.15-6.16, 6.18-6.19
  // The shear (6.5.2), when run.
  std::vector<ShearSample> shear;
  std::vector<analysis::Bin> shear_rose, shear_weighted_rose;        // at 0.015 % (Figs. 6.36-6.37)
  std::vector<analysis::Bin> early_sliding_rose, late_sliding_rose;  // at 0.005 % and 0.2 % (Figs. 6.38-6.41)
};

// Runs the case's stages up to "friction", and "shear" too when `shear`;
// with `out`, writes the figures' CSV files there (randall.csv, roses.csv,
// obliquity.csv, the contacts and particles at 100 kPa and at 0.1 %
// deviator strain, velocities at 0.005 %).
RandallRun run_randall(const std::filesystem::path& case_file, bool shear,
                       const std::optional<std::filesystem::path>& out = std::nullopt);

void print_randall(std::FILE* out, const RandallRun& run);

// What the thesis determines at 100 kPa (6.4.3): quasi-equilibrium, a
// near-circular rose, hardly any sliding contacts after friction is added;
// its coordination numbers (3.15 uniform, 3.57 graded) and F_max / F_mean
// (3.7, 4.8) are compared in the printout.
Verdict judge_randall_compression(const RandallRun& run);
// And in the constant-volume shear (6.5.2): quasi-static, sin(phi) rising
// steeply to about 0.3 (most of it by 0.1 % strain), the tangential
// forces' share of the deviator small, never more than a quarter of the
// contacts sliding, the anisotropy growing, the isotropic stress building.
// `sliding_bound`: Randall's 25 %; a reduced assembly's small circle
// fluctuates more.
Verdict judge_randall_shear(const RandallRun& run, double sliding_bound = 0.25);

}  // namespace dem::validation
