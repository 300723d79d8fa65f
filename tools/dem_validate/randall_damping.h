// Randall (1989) 6.5.1, Fig. 6.22: the constant-volume shear with the
// continuum strain rate under mass-proportional damping, swept over
// Randall's CON1 (subroutine MOTION: "When CON1 equals 1.0 then no damping
// is applied. For a CON1 value of 0.0 then the perturbation velocities are
// completely damped out"). Each CON1 value is one run of a case's shear
// (dem_validate randall-shear --con1 ...), measured as the thesis reports
// it: sin(phi) and the isotropic stress (Fig. 6.22), the out-of-balance to
// contact force ratio, and the perturbation velocities over the field's.
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <vector>

#include "dem/programme.h"
#include "dem/world.h"
#include "randall_assembly.h"
#include "verdict.h"

namespace dem::validation {

// CON1 is the share of a particle's perturbation velocity kept from one
// step to the next; the engine's global damping alpha (Cundall & Strack
// eq. 35, v' = (v (1 - alpha dt / 2) + F dt / m) / (1 + alpha dt / 2))
// keeps (1 - alpha dt / 2) / (1 + alpha dt / 2) of it, so
// alpha = 2 (1 - CON1) / ((1 + CON1) dt). The engine's damping is not
// changed: CON1 is only its other name.
double global_alpha_for_con1(double con1, double dt);
double con1_for_global_alpha(double alpha, double dt);

// Sets a case's shear stage to `setting`: CON1 as the stage's global
// damping (the rest of the damping as it sets it, or `in_effect`, the
// damping before it), at the stage's fixed time step; the deviator strain
// it runs to, its cycle cap scaled alike. Throws std::runtime_error for a
// CON1 outside [0, 1], a stage without a fixed time step (CON1 is per
// step) or a strain for a stage that stops at none.
void apply_shear_setting(StageDef& stage, const DampingDef& in_effect, const ShearSetting& setting);

// Randall 6.5.1: "When using the continuum tensor the velocity of each
// particle consists of two parts: a fixed velocity component dependant on
// the value of the imposed strain rate tensor, and a perturbation velocity
// resulting from out of balance forces". The root mean square of each over
// the assembly's particles, split as the law of motion splits them (the
// field where the particle stood the step before, motion.cpp); nothing
// when no continuum field moved the particles in the last step.
struct ContinuumPerturbation {
  double perturbation_rms = 0.0;  // m/s
  double field_rms = 0.0;         // m/s
};
std::optional<ContinuumPerturbation> continuum_perturbation(const World& world);

// The deviator strains at which the perturbation ratio is reported: the
// thesis's 0.5 % and 2 %, and the 0.05, 0.1 and 0.2 % a reduced case reaches.
inline constexpr std::array<double, 5> kPerturbationStrains = {0.0005, 0.001, 0.002, 0.005, 0.02};

// One run of the sweep, in the case's first region (the measurement
// circle) but for Delta F / F and the velocities (the whole assembly).
struct Con1Measured {
  double con1 = 1.0;
  std::uint64_t packing_seed = 0;
  double end_strain = 0.0;
  double peak_sin_phi = 0.0;
  double peak_strain = 0.0;        // the first strain within 5 % of the peak (measure_randall)
  double mean_stress_start = 0.0;  // Pa, the isotropic stress as the shear starts
  double mean_stress_end = 0.0;    // Pa, at its end
  double largest_out_of_balance = 0.0;
  // Perturbation RMS over field RMS at kPerturbationStrains (the sample
  // nearest each, within 5 % of it); none where the shear did not reach it.
  std::array<std::optional<double>, kPerturbationStrains.size()> ratio_at;
  double smallest_ratio = 0.0, largest_ratio = 0.0;  // over the shear's samples with a field
  double stress_rise() const { return mean_stress_start > 0.0 ? mean_stress_end / mean_stress_start - 1.0 : 0.0; }
};

Con1Measured measure_con1(const RandallRun& run, double con1);

// The median of each figure over packings of one CON1 value, with the
// smallest and the largest.
struct Con1Summary {
  double con1 = 1.0;
  std::vector<Con1Measured> packings;
  Con1Measured median, low, high;
};
Con1Summary summarise_con1(double con1, const std::vector<Con1Measured>& packings);

// The table: one row per CON1 value (median, and the spread when there
// are several packings), then the thesis's statements beside what was
// measured.
void print_con1_sweep(std::FILE* out, const std::vector<Con1Summary>& sweep);

// What the sweep can judge against the seed (only what agrees with it is
// asserted; docs/VALIDATION.md 6.5.1 gives the rest).
Verdict judge_con1_sweep(const std::vector<Con1Summary>& sweep);

// Runs the case's shear once for each CON1 value and packing seed (the
// case's own when none) into out/con1_<value>/[packing_<seed>/], writes
// each run's perturbation.csv there and out/con1.csv (one row a run), and
// prints and judges the sweep.
Verdict report_con1_sweep(const std::filesystem::path& case_file, const std::vector<double>& con1s,
                          const std::filesystem::path& out, const std::vector<std::uint64_t>& seeds,
                          std::optional<double> to_strain);

}  // namespace dem::validation
