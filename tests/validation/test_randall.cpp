// Randall (1989) chapter 6 on reduced assemblies, short enough for the
// suite: the graded assembly (120 spheres) at 100 kPa and sheared at
// constant volume to 0.2 % (6.4.3, 6.5.2); a hopper discharging through
// two orifices (6.2). The full runs are dem_validate's randall-shear,
// hopper and deposition (docs/VALIDATION.md); the checks are theirs.
#include <gtest/gtest.h>

#include <filesystem>

#include "hopper.h"
#include "randall_assembly.h"

namespace dem::validation {
namespace {

const std::filesystem::path kCases = DEM_CASES_DIR "/randall";

TEST(Randall, GradedAssemblyAt100KpaThenShearedAtConstantVolume) {
  const RandallRun run = run_randall(kCases / "graded_reduced.case.txtpb", true);
  print_randall(stdout, run);
  Verdict verdict = judge_randall_compression(run);
  // A circle of some 90 spheres: its share of sliding contacts fluctuates
  // around Randall's 25 % bound (24 % in the full assembly's circles).
  verdict.add(judge_randall_shear(run, 0.3));
  verdict.print(stdout, run.name);
  EXPECT_TRUE(verdict.passed()) << verdict;
}

// "Increasing the orifice width increased the discharge rate" (6.2), on
// 200 spheres through 5 and 10 mm at a half-angle of 30 degrees.
TEST(Randall, AWiderOrificeDischargesFaster) {
  std::vector<HopperRun> runs;
  for (const double orifice : {0.005, 0.010})
    runs.push_back(run_hopper(kCases / "hopper_reduced.case.txtpb", 30.0, orifice));
  print_hopper(stdout, runs);
  const Verdict verdict = judge_hopper(runs);
  verdict.print(stdout, "hopper");
  EXPECT_TRUE(verdict.passed()) << verdict;
}

}  // namespace
}  // namespace dem::validation
