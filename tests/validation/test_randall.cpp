// Randall (1989) chapter 6 on reduced assemblies, short enough for the
// suite: the graded assembly (120 spheres, three packings) at 100 kPa and
// sheared at constant volume to 0.2 %, with its contact stresses at 0, 0.1
// and 0.2 % and the contacts it breaks by 0.1 % (6.4.3, 6.5.2, Figs. 6.35,
// 6.42-6.43); the centripetal
// compaction (200 spheres, three packings) sheared at constant mean stress
// to 1.5 % (6.4.2); a hopper discharging through two orifices (6.2); a
// pluvial deposition of 200 spheres (three packings) into a container (6.3). The
// full runs are dem_validate's randall-shear, randall-centripetal, hopper
// and deposition (docs/VALIDATION.md); the checks are theirs.
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>

#include "deposition.h"
#include "hopper.h"
#include "randall_assembly.h"
#include "randall_centripetal.h"
#include "randall_damping.h"

namespace dem::validation {
namespace {

const std::filesystem::path kCases = DEM_CASES_DIR "/randall";

// Randall's figures that the reduced assembly, prepared his way, does not
// reach: printed by the verdict, not asserted. docs/VALIDATION.md ("6.4.3
// and 6.5.2") gives the evidence: the porosity (16 % against his 14 %) in
// the full assemblies too; F_max / F_mean and the peak of sin(phi), which
// circles of some 90 spheres miss by more than the full graded assembly
// (it meets F_max / F_mean, and its peak on one packing of three).
const std::set<std::string> kDisagreements = {
    "porosity (6.5.2)",
    "F_max / F_mean at 100 kPa (6.4.3)",
    "peak sin(phi) (Fig. 6.24)",
};

// Three packings of the graded assembly reduced to 120 spheres, prepared as
// Randall's (dense generation, continuum strain-rate compression without
// friction, quasi-equilibrium, friction) and sheared at constant volume at
// his rate to 0.2 %; the median packing judged as the full assemblies are.
TEST(Randall, GradedAssemblyAt100KpaThenShearedAtConstantVolume) {
  const Verdict verdict = report_randall(kCases / "graded_reduced.case.txtpb", true, std::nullopt, {1989, 1, 2},
                                         RandallTolerances::reduced());
  verdict.print(stdout, "randall_graded_reduced");
  for (const Check& check : verdict.checks()) {
    if (!kDisagreements.contains(check.name)) {
      EXPECT_TRUE(check.passed) << check.name << ": " << check.detail;
    }
  }
}

// Randall's 6.4.2 figures that the centripetal compaction of 200 spheres,
// done his way, does not reproduce: printed by the verdict, not asserted.
// docs/VALIDATION.md ("6.4.2") gives the evidence: the largest circle turns
// to expand long before 0.5 % in the full assembly too; the smallest circle
// here holds some 30 spheres, whose sin(phi) and volumetric strain scatter
// from packing to packing, and the largest some 120, whose expansion
// levels off within the test; one packing (seed 2) creeps at 100 kPa, a
// corner wall 9 % below its target when the load stage reaches its cap
// (its circle reads 90 kPa). The full assembly's circles are judged by
// dem_validate.
const std::set<std::string> kCentripetalDisagreements = {
    "compacted, at equilibrium and at 100 kPa (the stages met their conditions)",
    "largest spread of the three circles' sin(phi) from 0.5 % (Fig. 6.7)",
    "deviator strain where the largest circle turns to expand, from 0.25 % (around 0.5 %)",
    "largest circle's expansion over the last quarter of the test",
    "deviator strain where the smallest circle turns to expand (from the start)",
};

// The centripetal compaction of 200 spheres on three packings: compacted
// without friction by the field, bounded, the field removed, friction
// added, 100 kPa, then sheared at constant mean stress to 1.5 % while three
// circles of 15, 34 and 62 % of the particles are measured (Figs. 6.4-6.8);
// the median packing judged as the full assembly is.
TEST(Randall, CentripetalCompactionThenShearedAtConstantMeanStress) {
  const Verdict verdict = report_centripetal(kCases / "centripetal_reduced.case.txtpb", std::nullopt, {1989, 1, 2});
  verdict.print(stdout, "randall_centripetal_reduced");
  for (const Check& check : verdict.checks()) {
    if (!kCentripetalDisagreements.contains(check.name)) {
      EXPECT_TRUE(check.passed) << check.name << ": " << check.detail;
    }
  }
}

// Randall's 6.3 statements that the deposition, redone here, does not show:
// printed by the verdict, not asserted. docs/VALIDATION.md ("6.3") gives
// the evidence: the side walls carry next to none of the bed's weight
// (no Janssen arching onto them), and no particle that came to rest in an
// arch anywhere in the bed later dropped (no collapse, at the corners or
// elsewhere), in the full bed too.
const std::set<std::string> kDepositionDisagreements = {
    "side walls' share of the weight over Janssen's at full friction (median packing; arching)",
    "particles in the corners whose arch collapsed (all packings)",
    "collapses per resting particle, corners over the middle of the floor",
};

// Webster's pluvial deposition (6.3) on 200 spheres of two sizes and three
// packings: the rain lands at the Rayleigh step, which Randall found too
// large near equilibrium (above his 0.3 of the particle-wise critical
// step), and the bed settles at 0.3 of it, carried by the container;
// arching onto the walls and collapses at the corners measured.
TEST(Randall, PluvialDepositionIntoAContainer) {
  const Verdict verdict =
      report_deposition(kCases / "pluvial_deposition_reduced.case.txtpb", std::nullopt, {1989, 1, 2});
  verdict.print(stdout, "randall_pluvial_deposition_reduced");
  for (const Check& check : verdict.checks()) {
    if (!kDepositionDisagreements.contains(check.name)) {
      EXPECT_TRUE(check.passed) << check.name << ": " << check.detail;
    }
  }
}

// "Increasing the orifice width increased the discharge rate, although it
// did not seem to affect the duration of the initial acceleration stage"
// (6.2), on 200 spheres through 5 and 10 mm at a half-angle of 30 degrees.
TEST(Randall, AWiderOrificeDischargesFaster) {
  std::vector<HopperRun> runs;
  for (const double orifice : {0.005, 0.010})
    runs.push_back(run_hopper(kCases / "hopper_reduced.case.txtpb", 30.0, orifice));
  print_hopper(stdout, runs);
  const Verdict verdict = judge_hopper(runs);
  verdict.print(stdout, "hopper");
  EXPECT_TRUE(verdict.passed()) << verdict;
}

// Randall 6.5.1's CON1 ("When CON1 equals 1.0 then no damping is applied.
// For a CON1 value of 0.0 then the perturbation velocities are completely
// damped out") as the engine's global damping at the shear's step: the
// Fig. 6.23 case's 4.62e+06 /s is CON1 0.75 at 6.19e-08 s, and a --con1
// sweep sets the shear stage to it. The sweep itself (Fig. 6.22) is
// print-only, dem_validate randall-shear --con1: its isotropic stress
// ordering holds on two packings of three (docs/VALIDATION.md 6.5.1).
TEST(Randall, Con1IsThePerturbationVelocityKeptAStep) {
  const double dt = 6.19e-08;
  EXPECT_NEAR(global_alpha_for_con1(0.75, dt), 4.62e+06, 0.005e+06);
  EXPECT_DOUBLE_EQ(global_alpha_for_con1(1.0, dt), 0.0);
  for (const double con1 : {0.0, 0.25, 0.5, 0.8, 0.99}) {
    EXPECT_NEAR(con1_for_global_alpha(global_alpha_for_con1(con1, dt), dt), con1, 1e-12) << con1;
  }
  StageDef shear;
  shear.name = "shear";
  shear.time_step = TimeStepSetting{0.0, dt};
  shear.cycles = 600000;
  shear.until.deviator_strain_above = 0.002;
  DampingDef in_effect;
  in_effect.contact_beta = 1e-6;
  apply_shear_setting(shear, in_effect, ShearSetting{0.25, 0.02});
  ASSERT_TRUE(shear.damping.has_value());
  EXPECT_DOUBLE_EQ(shear.damping->global_alpha, global_alpha_for_con1(0.25, dt));
  EXPECT_DOUBLE_EQ(shear.damping->contact_beta, 1e-6);  // the rest of the damping kept
  EXPECT_EQ(shear.cycles, 6000000u);                    // the cap scaled with the strain
  EXPECT_DOUBLE_EQ(*shear.until.deviator_strain_above, 0.02);
  StageDef fraction_step = shear;
  fraction_step.time_step = TimeStepSetting{0.1, 0.0};
  EXPECT_THROW(apply_shear_setting(fraction_step, in_effect, ShearSetting{0.5, std::nullopt}), std::runtime_error);
}

}  // namespace
}  // namespace dem::validation
