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

#include "dem/analysis/contact_changes.h"
#include "dem/analysis/distributions.h"
#include "dem/analysis/region_measures.h"
#include "randall_contact_stresses.h"
#include "verdict.h"

namespace dem::validation {

// The assembly at one moment of the shear.
struct ShearSample {
  std::uint64_t cycle = 0;
  double deviator_strain = 0.0;  // the box's, sigma_y's axis shortened, sigma_x's lengthened
  double volumetric_strain = 0.0;
  double out_of_balance = 0.0;                    // Delta F / F
  std::vector<analysis::RegionMeasures> regions;  // the case's regions, in order
  // Under a continuum field (6.5.1): the particles' perturbation velocities
  // against the field's (randall_damping.h); none without a field.
  std::optional<double> perturbation_rms, field_rms;  // m/s
};

// What Randall measured on one of his two assemblies (6.4.3, 6.5.2,
// Fig. 6.24), which a run is judged against.
struct RandallFigures {
  std::string assembly;       // "graded" or "uniform"
  double porosity = 0.0;      // "14% and 16%" (6.5.2)
  double coordination = 0.0;  // 3.57 graded, 3.15 uniform (6.4.3)
  double force_ratio = 0.0;   // F_max / F_mean: 0.59/0.123, 0.53/0.143 N (6.4.3)
  double peak_sin_phi = 0.0;  // "around 0.36", "approximately 0.3" (Fig. 6.24)
  // The deviator strains between which sin(phi) reaches its peak (95 % of
  // its largest value): graded "by 0.05%" read as by 0.1 %, a factor of two;
  // uniform "just after 0.1%" as between 0.1 and 0.2 %.
  double peak_strain_low = 0.0;
  double peak_strain_high = 0.0;
  double tangential_share = 0.0;  // of the deviator: "14% for the graded and 15% for the uniform"
};

// Randall's figures for the assembly a case stands for, by its name
// ("randall_graded..." or "randall_uniform..."); throws for any other.
RandallFigures randall_figures(const std::string& case_name);

struct RandallRun {
  std::string name;
  RandallFigures figures;
  std::uint64_t packing_seed = 0;
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
  std::vector<ContactStressState> contact_stresses;                  // at 0, 0.1 and 0.2 % (Figs. 6.42-6.43)
  analysis::ContactChanges lattice;                                  // from the start of the shear to 0.1 % (Fig. 6.35)
  bool lattice_taken = false;
};

// What a run may change in the case's shear stage (6.5.1's sweep): the
// mass-proportional damping as Randall's CON1, the velocity kept per step
// (randall_damping.h), and the deviator strain the shear runs to (its
// cycle cap scaled with it).
struct ShearSetting {
  std::optional<double> con1;
  std::optional<double> to_strain;
};

// Runs the case's stages up to "friction", and "shear" too when `shear`,
// on its own packing or on `packing_seed`'s; with `out`, writes the
// figures' CSV files there (randall.csv, roses.csv, obliquity.csv, the
// contacts and particles at 100 kPa and at 0.1 % deviator strain,
// velocities at 0.005 %, the contact stresses at 0, 0.1 and 0.2 %).
RandallRun run_randall(const std::filesystem::path& case_file, bool shear,
                       const std::optional<std::filesystem::path>& out = std::nullopt,
                       std::optional<std::uint64_t> packing_seed = std::nullopt, const ShearSetting& setting = {});

void print_randall(std::FILE* out, const RandallRun& run);

// The figures a run is judged on, in its first region (a measurement
// circle well inside the walls): of one packing, or the median of each
// over several.
struct RandallMeasured {
  std::string label;             // "packing seed 1989", "median of 3"
  bool compressed = false;       // compression and friction stages settled (in every packing)
  double box_stress = 0.0;       // Pa, the walls' mean at rest
  double interior_stress = 0.0;  // Pa, the region's mean stress at rest
  double out_of_balance = 0.0;   // Delta F / F at rest
  double anisotropy = 0.0;       // Phi_1 - Phi_2 at rest
  double sliding_at_rest = 0.0;
  double porosity = 0.0;
  double coordination = 0.0;
  double mechanical_coordination = 0.0;  // without rattlers
  double force_ratio = 0.0;              // F_max / F_mean
  bool sheared = false;
  double largest_out_of_balance = 0.0;  // during the shear
  double peak_sin_phi = 0.0;
  double peak_strain = 0.0;       // the first strain within 5 % of the peak
  double tangential_share = 0.0;  // of the deviator there
  double largest_sliding = 0.0;
  double induced_anisotropy = 0.0;  // Phi_yy - Phi_xx gained in the shear
  double mean_stress_gain = 0.0;    // the region's mean stress at the end over at the start
  // Fig. 6.35: the contacts broken by 0.1 %, as a share of those at the
  // start, and the shares of the broken ones within 45 degrees of the
  // extension (x) axis and of the formed ones of the compression (y) axis.
  double broken_share = 0.0;
  double broken_along_extension = 0.0;
  double formed_along_compression = 0.0;
  ContactStressFigures contact_stress;  // Figs. 6.42-6.43
};

RandallMeasured measure_randall(const RandallRun& run);
// Each figure's median over the packings (compressed when all were).
RandallMeasured median_of(const std::vector<RandallMeasured>& packings);
// One line per packing, then the medians.
void print_packings(std::FILE* out, const std::vector<RandallMeasured>& packings);

// How near a run must come to Randall's figures. The full assemblies are
// judged with the defaults; a reduced one (a circle of some 90 spheres)
// with `reduced()`: what a small sample scatters more.
struct RandallTolerances {
  double porosity = 0.01;          // absolute: "within 1 point"
  double coordination = 0.15;      // absolute
  double force_ratio = 0.25;       // relative: a largest force of one sample
  double interior_stress = 0.1;    // relative, against the walls' 100 kPa
  double peak_sin_phi = 0.04;      // absolute
  double tangential_share = 0.05;  // absolute
  double sliding_bound = 0.25;     // "never more than 25% of contacts are sliding"
  static RandallTolerances reduced();
};

// What the thesis determines at 100 kPa (6.4.3): quasi-equilibrium, a
// near-circular rose, hardly any sliding contacts after friction is added,
// the interior at the walls' stress, and his porosity, coordination and
// F_max / F_mean for the assembly; and the theory's isostatic coordination
// of a frictionless jammed packing.
Verdict judge_randall_compression(const RandallMeasured& measured, const RandallFigures& figures,
                                  const RandallTolerances& tolerances = {});
// And in the constant-volume shear (6.5.2): quasi-static, sin(phi) rising
// steeply to Randall's peak by his strain, the tangential forces' share of
// the deviator his, never more than a quarter of the contacts sliding, the
// anisotropy growing, the isotropic stress building.
Verdict judge_randall_shear(const RandallMeasured& measured, const RandallFigures& figures,
                            const RandallTolerances& tolerances = {});

// Runs the case on each seed (its own packing when `seeds` is empty), into
// out/packing_<seed>/ when there are several, prints each run and the
// packings' table, and judges the median packing against Randall's
// figures.
Verdict report_randall(const std::filesystem::path& case_file, bool shear,
                       const std::optional<std::filesystem::path>& out, const std::vector<std::uint64_t>& seeds,
                       const RandallTolerances& tolerances = {});

}  // namespace dem::validation
